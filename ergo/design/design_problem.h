// DesignProblem: the design objective of paper §4, x ↦ φ(x) = ζ(x) + γ ψ(x), and its exact
// gradient by the implicit function theorem (Eq. 17–20): solve the equilibrium y*(x)
// (warm-started from the nearest earlier state), then one adjoint solve K̂ z = (∂ζ/∂y)ᵀ with
// the exact Hessian at y*, and dφ/dx = ∂ζ/∂x − zᵀ ∂G/∂x + γ ∂ψ/∂x, where G = ∂E/∂y is the
// equilibrium residual and ζ sums the bi-directional pressures of the skin (its own
// springs) and of the support (springs of support vertices inside the deformed skin).
//
// Copies are independent (own support trees, solver and warm-start cache) and share the
// evaluation counters, so an optimiser can probe several designs in parallel threads.
//
//   DesignProblem problem(body, support_mesh, start_state, options);
//   DesignEvaluation e = problem.Evaluate(problem.InitialDesign(), /*with_gradient=*/true);
//   if (!e.ok) LOG(ERROR) << e.message;   // the equilibrium did not converge
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/elastic_part.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/rest_extension.h"
#include "ergo/contact/support.h"
#include "ergo/design/evaluation_timing.h"
#include "ergo/design/support_parameterization.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/pressure_cost.h"
#include "ergo/ergonomics/smoothness_term.h"
#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {

// Where each evaluation's equilibrium starts.
enum class DesignPlacement {
  // The body placed afresh: the start pose moved along the load to `placement_gap` above
  // the support at x, as a person steps onto the printed part. The score is then a function
  // of the design alone (DESIGN.md §8), and a design is judged as it will be used.
  kFresh,
  // Warm-started from the equilibrium of the nearest design evaluated before (the paper's
  // §4.1; the first evaluation places the body afresh): cheaper, but contact with a sculpted
  // support can have several nearby equilibria,
  // and a gain may exist only on the path the optimiser followed.
  kFollowed,
  // Fresh placements as anchors: a design within `anchor_move` (largest vertex move) of an
  // earlier freshly placed design is warm-started from that anchor's equilibrium (one hop,
  // never from a warm-started one), any other is placed afresh and becomes an anchor. The
  // path cannot drift from the equilibria a fresh placement finds by more than one hop, at
  // about the cost of kFollowed.
  kAnchored,
};

// "fresh", "followed", "anchored"; and back (false for any other word).
const char* DesignPlacementName(DesignPlacement placement);
bool ParseDesignPlacement(const std::string& name, DesignPlacement* placement);

struct DesignOptions {
  EquilibriumOptions equilibrium;
  DesignPlacement placement = DesignPlacement::kFresh;
  double placement_gap = 1e-3;             // m, for kFresh and kAnchored
  double anchor_move = 5e-4;               // m, for kAnchored
  PressureCostOptions pressure;            // exponent e, smoothing λ_p
  TaubinParameters taubin{0.5, -0.53, 1};  // ψ's Taubin λ, μ, m (Eq. 14)
  double gamma = 0;                        // weight of ψ in φ (see AutoGamma)
  DesignParameterization parameterization = DesignParameterization::kPositions;
  double filter_radius = 0;  // m; the filter's radius r when parameterization == kFiltered
  // kFiltered: design variables scaled so that the optimiser's inner product is the L² one
  // (ergo/design/support_parameterization.h); false: one raw θ per vertex.
  bool l2_design_metric = false;
  std::vector<bool> active;   // movable support vertices; empty = all
  int warm_start_cache = 16;  // equilibria kept for warm starts
  // Warm starts from the last equilibrium after a design step of at most 0.5 mm are first
  // moved along the tangent dy/dx·δx (one linear solve with the last Newton factor) when
  // that lowers the energy: fewer Newton iterations (quick shoe: 0.1 mm 3 → 2, 0.3 mm 5 → 4).
  bool tangent_predictor = true;
  // Whether ζ counts the support's vertices inside the skin (the paper's bi-directional
  // score) or the skin's side alone, what the person feels. Under one-way contact the
  // support's samples push nothing, and their term depends on how the two meshes interleave
  // (ergo/design/README.md, "Designs on two sole meshes").
  bool score_support_side = true;
  // The support as foam whose rest shape is the design (paper §4.3; null: rigid, its
  // surface is the design). The support mesh given to the problem must be its boundary at rest
  // (ElasticPart::boundary().surface); `active` flags the designed boundary vertices (the held
  // base never is), the interior's rest positions follow harmonically (RestExtension).
  std::shared_ptr<const ElasticPart> soft_support;
};

struct DesignEvaluation {
  bool ok = false;
  std::string message;  // why not ok (the equilibrium's report), or "ok"
  double phi = 0, zeta = 0, psi = 0;
  double zeta_human = 0, zeta_support = 0;  // ζ's skin and support halves
  Eigen::VectorXd gradient;                 // dφ/dx (when requested)
  Eigen::VectorXd zeta_gradient;            // dζ/dx
  Eigen::VectorXd psi_gradient;             // dψ/dx
  EquilibriumResult equilibrium;
  // The equilibrium's springs, per-vertex forces and both surfaces' pressures: what the
  // reports and pictures show (nothing is rebuilt for output).
  ContactPressures pressures;
  // A soft support: the foam at this design's rest shape, as the equilibrium used it (its
  // deformed positions are the state's support displacement added). Null for a rigid one.
  std::shared_ptr<const ElasticPart> soft_support;
  // Where this evaluation's time went (its total is this evaluation's wall time; the
  // equilibrium's parts are those of `equilibrium`, gathered with the rest).
  EvaluationTiming timing;
};

// Evaluation counts shared by a problem and all its copies.
struct DesignCounters {
  std::atomic<long> evaluations{0};
  std::atomic<long> gradients{0};
  std::atomic<long> failures{0};
  std::atomic<long> newton_iterations{0};
  std::atomic<long> nanoseconds{0};
  double seconds() const { return 1e-9 * static_cast<double>(nanoseconds.load()); }
};

class DesignProblem {
 public:
  // Keeps a reference to `body`. `start` places the body for the first solve (e.g. a rest
  // state lifted above the support). Throws InputError for an unusable support mesh.
  DesignProblem(const LayeredBody& body, const TriMesh& support, const BodyState& start,
                const DesignOptions& options);
  DesignProblem(const DesignProblem& other);
  DesignProblem& operator=(const DesignProblem&) = delete;

  int NumParameters() const { return parameterization_.size(); }
  Eigen::VectorXd InitialDesign() const { return parameterization_.InitialDesign(); }
  const SupportParameterization& parameterization() const { return parameterization_; }
  const LayeredBody& body() const { return body_; }
  const DesignOptions& options() const { return options_; }
  const TriMesh& initial_support() const { return initial_support_; }
  void set_gamma(double gamma) { options_.gamma = gamma; }
  void set_placement(DesignPlacement placement) { options_.placement = placement; }
  void set_tangent_predictor(bool on) { options_.tangent_predictor = on; }
  void set_contact_stiffness(double k);

  // φ, ζ, ψ (and with_gradient: their gradients) at design x. Thread-compatible: one
  // thread per copy.
  DesignEvaluation Evaluate(const Eigen::VectorXd& x, bool with_gradient);

  // The support surface at design x.
  TriMesh SupportAt(const Eigen::VectorXd& x) const;

  const DesignCounters& counters() const { return *counters_; }
  // The most recent converged equilibrium state (for warm starts elsewhere).
  const BodyState& last_state() const { return last_state_; }
  // The start pose (kFresh evaluations are placed from it).
  const BodyState& start() const { return start_; }
  // Moves the start pose (a different placement of the same body); clears the warm starts.
  void set_start(const BodyState& start);
  // Forgets the warm starts and anchors: the next evaluation places the body afresh.
  void ClearWarmStarts() { set_start(start_); }

 private:
  // The cached equilibrium of the design nearest to x; *from_last: it is the last solve's.
  BodyState WarmStart(const Eigen::VectorXd& x, bool* from_last = nullptr) const;
  // The last equilibrium moved along the tangent to design x (or left as is where that does
  // not lower the energy on the support at x, which must be in place).
  BodyState TangentPrediction(const Eigen::VectorXd& x) const;
  // The start pose placed `placement_gap` above the current support (kFresh).
  BodyState FreshStart() const;
  void Remember(const Eigen::VectorXd& x, const BodyState& state);

  const LayeredBody& body_;
  DesignOptions options_;
  TriMesh initial_support_;
  SupportParameterization parameterization_;
  SparseMatrix support_laplacian_;
  Support support_;                     // the support at the current x
  ContactPressureEvaluator pressures_;  // skin/support springs → pressures
  EquilibriumSolver solver_;
  SparseCholesky adjoint_cholesky_;  // exact K̂ at y*, same pattern as Newton
  BodyState start_;                  // the placement every kFresh evaluation starts from
  BodyState last_state_;
  Eigen::VectorXd last_x_;      // the design of last_state_ (empty until a solve converged)
  bool last_solve_ok_ = false;  // the solver's last evaluation is at last_state_
  std::vector<std::pair<Eigen::VectorXd, BodyState>> cache_;
  std::vector<std::pair<Eigen::VectorXd, BodyState>> anchors_;  // kAnchored: fresh placements
  std::shared_ptr<DesignCounters> counters_;
  // A soft support: its designed vertices and how the interior follows (own copy per problem
  // copy: the extension's factor is not shared between threads).
  std::vector<bool> rest_designed_;
  std::optional<RestExtension> rest_extension_;
};

// γ = κ · 10^j with κ such that ζ(x₀) = κ ψ(x₀) (paper §4.1). Evaluates x₀ once; returns
// a negative value with `message` set if ψ(x₀) = 0 or the evaluation fails.
double AutoGamma(DesignProblem& problem, int power_of_ten, std::string* message);
// The same from an evaluation of x₀ already made (which must be ok).
double AutoGammaFrom(const DesignEvaluation& at_x0, int power_of_ten, std::string* message);

}  // namespace ergo
