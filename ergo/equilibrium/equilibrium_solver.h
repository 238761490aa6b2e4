// EquilibriumSolver: the static contact equilibrium of a layered body on a rigid or soft
// support (paper §3.3–3.4, §4.3): Newton–Raphson on the reduced coordinates y = (u^F, q[, u^S])
// with K̂ (Eq. 7) factorised by CHOLMOD (symbolic analysis once per body and whenever a soft
// support's contact pattern changes, numeric refactorisation per step), a golden-section
// line search on the energy of Eq. 9 with collision detection at every trial point, and K̂ + αM
// while no vertex touches the support. Converges on the force residual relative to the load (weight
// + external force).
//
// Newton matrix: the exact K̂ when it is positive definite (quadratic convergence near a
// stable equilibrium), otherwise K̂ with every element block projected to PSD. The
// projection alone discards the negative curvature of compressed tissue and of the
// gravity lever arms and converges only linearly (measured: 42 vs 9 iterations for a soft
// cube in a pit, README); both matrices give descent directions.
//
//   EquilibriumSolver solver(body, options);
//   EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, lift));
//   if (!result.converged) LOG(ERROR) << result.BriefReport();
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ergo/body/body_state.h"
#include "ergo/contact/support.h"
#include "ergo/equilibrium/total_potential.h"
#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {

// One Newton iteration, as EquilibriumOptions::progress sees it.
struct NewtonIterationReport {
  int iteration = 0;
  double residual = 0;       // N, at the iterate the step started from
  double step = 0;           // η, the line search's fraction of the Newton step
  int contact_vertices = 0;  // skin vertices inside the support at that iterate
  // The contact's active set against the previous iterate: skin vertices that entered or
  // left the support, and those whose closest feature changed (the piecewise energy then
  // switches formula, so a Newton model built on the old set is off for them).
  int contacts_entered = 0, contacts_left = 0, feature_switches = 0;
};

struct EquilibriumOptions {
  // κ of the area-weighted contact (ergo/contact/surface_contact.h): contact pressure per
  // metre of penetration, Pa/m. Mesh-independent: a spring's k is κ times its vertex area.
  double contact_stiffness = 1e8;
  // α, the skin's share of the contact quadrature (SurfaceContactOptions::skin_share); 0:
  // chosen from the meshes at the first solve (ContactSkinShare).
  double contact_skin_share = 0;
  // Springs of support vertices inside the skin in the equilibrium too (two-way); false, the
  // default: they are scored but push nothing, the paper's uni-directional equilibrium with
  // its bi-directional score under one pressure law (SurfaceContactOptions::support_springs;
  // ergo/design/README.md has the measurements that chose it).
  bool contact_support_springs = false;
  // Converged when ResidualNorm ≤ relative_tolerance · |weight + external force|.
  double relative_tolerance = 1e-8;
  int max_iterations = 100;
  // Accepted as converged (kStalled) when the residual has stayed ≤ stalled_relative_tolerance
  // · |load| for stall_iterations iterations in a row without reaching relative_tolerance:
  // skin vertices switching between a faceted support's Voronoi regions can keep Newton
  // from the strict tolerance indefinitely (README, Performance: the 40k trace), while a
  // residual of 1e-6 of the load moves the state by far less than the penetrations the score
  // reads. 0 iterations: never (the strict tolerance or the cap).
  double stalled_relative_tolerance = 1e-6;
  int stall_iterations = 5;
  // α of "K + αM" while nothing touches the support, 1/s² (paper: 1e3 chair, 1e6 shoe,
  // 1e4 mouse). Each free-fall step then moves the body about |g|/α (before the line
  // search's expansion).
  double free_fall_mass_scale = 1e3;
  int max_line_search_evaluations = 30;
  // Line search: when the full Newton step fails the Armijo test, try the quadratic model's
  // step first and keep it if it decreases enough (GoldenSectionOptions::interpolate);
  // false = the paper's golden-section minimisation to 1 % of the step at every such step.
  bool interpolated_line_search = false;
  // A Newton step moving any vertex farther than this fraction of the body's size is
  // shortened first (a body balanced on a point has a nearly free tipping mode).
  double max_step_fraction = 0.05;
  // Try the exact Hessian first (see above); false = always the PSD projection.
  bool exact_newton_first = true;
  // Solve the Newton system by conjugate gradients preconditioned with the last Cholesky
  // factor (from an earlier step or an earlier solve of a nearby problem) before
  // refactorising; factorisation dominates Newton's time (README, Performance).
  bool reuse_factorization = true;
  int max_pcg_iterations = 12;
  // Called after every Newton iteration.
  std::function<void(const NewtonIterationReport&)> progress;
  // If set, checked before every Newton iteration: true ends the solve (kInterrupted).
  const std::atomic<bool>* stop = nullptr;
};

enum class EquilibriumStatus {
  kConverged,
  kStalled,            // converged to stalled_relative_tolerance, not relative_tolerance
  kIterationCap,       // max_iterations reached
  kLineSearchFailure,  // no step length decreased the energy
  kNonFinite,          // NaN or Inf in the energy, residual or step
  kNoContact,          // the body fell past the support without touching it
  kUnconstrained,      // a free core DOF meets no resistance (e.g. sliding on a plane)
  kInterrupted,        // EquilibriumOptions::stop was set
};

const char* EquilibriumStatusName(EquilibriumStatus status);

struct EquilibriumResult {
  BodyState state;
  bool converged = false;  // kConverged or kStalled
  EquilibriumStatus status = EquilibriumStatus::kIterationCap;
  std::string message;      // why it stopped, in words
  int iterations = 0;       // Newton iterations
  int projected_steps = 0;  // iterations that fell back to the PSD-projected K̂
  int factorizations = 0;   // numeric Cholesky factorisations (regularised retries included)
  // Symbolic analyses: none for a rigid support (done once per body, in the constructor); with
  // a soft support, one whenever the contact's cross blocks changed K̂'s pattern. Their time
  // is in factorization_seconds.
  int analyses = 0;
  double analysis_seconds = 0;  // their part of factorization_seconds
  int pcg_iterations = 0;       // conjugate-gradient iterations on reused factors
  int line_search_trials = 0;   // energy evaluations of the line searches
  // Active-set changes summed over the iterations (NewtonIterationReport); with a start out
  // of contact, entered − left = contact_vertices.
  int contacts_entered = 0, contacts_left = 0, feature_switches = 0;
  double residual = 0;  // final ResidualNorm, N
  double relative_residual = 0;
  double energy = 0;           // J
  int contact_vertices = 0;    // skin vertices inside the support
  int contact_springs = 0;     // springs that push (both kinds when two-way)
  double max_penetration = 0;  // m
  Eigen::Vector3d contact_force = Eigen::Vector3d::Zero();  // Σ contact forces on the body, N
  // Seconds spent, by part (disjoint intervals inside total_seconds): assembly of the elastic
  // terms and reduction; contact detection and springs at the iterates (and the free-fall
  // clearance queries); numeric factorisations; solves (PCG on reused factors, triangular
  // solves); the line search's trials (energy with contact detection at each).
  double assembly_seconds = 0, contact_seconds = 0, factorization_seconds = 0, solve_seconds = 0,
         line_search_seconds = 0, total_seconds = 0;

  std::string BriefReport() const;  // one line
  std::string FullReport() const;   // several lines with the time split
};

class EquilibriumSolver {
 public:
  // Keeps a reference to `body`. Analyses the Hessian pattern once (CHOLMOD symbolic) for a
  // rigid support. `soft_support`: the support as a deformable part (TotalPotential), whose
  // K̂ pattern follows the contact set and is re-analysed when it changes; Solve then takes
  // its boundary at rest (SoftSupportSurface) and returns its displacements in the state.
  EquilibriumSolver(const LayeredBody& body, const EquilibriumOptions& options,
                    std::shared_ptr<const ElasticPart> soft_support = nullptr);

  // Solves from `start` (warm start: any earlier state, even for another support shape).
  EquilibriumResult Solve(const Support& support, const BodyState& start);

  const TotalPotential& potential() const { return potential_; }
  const EquilibriumOptions& options() const { return options_; }
  void set_contact_stiffness(double k);
  // Another rest shape of the soft support (TotalPotential::set_soft_support).
  void set_soft_support(std::shared_ptr<const ElasticPart> part) {
    potential_.set_soft_support(std::move(part));
  }

  // Per tet-mesh-vertex anchors of the last solve (closest-point hints for the next).
  std::vector<SupportPoint>& hints() { return hints_; }

  // The evaluation at the state the last Solve returned (positions, contact springs with
  // their Hessians, reduced gradient and — when `last_hessian_exact()` — the exact K̂ there),
  // so callers (the adjoint gradient) need not assemble it again. Valid until the next Solve.
  const TotalPotential::Evaluation& last_evaluation() const { return last_; }
  // The last Cholesky factor (of the Newton matrix at or near the returned state): a
  // preconditioner for the adjoint solve.
  const SparseCholesky& factor() const { return cholesky_; }
  bool last_hessian_exact() const { return last_exact_; }

 private:
  // A message naming the free core DOFs (translations perpendicular to every contact
  // normal) along which the contacts give no stiffness, or "" if there is none.
  std::string UnconstrainedTranslations(const TotalPotential::Evaluation& evaluation) const;
  bool FellPastSupport(const Vertices& positions, const Support& support) const;
  // Re-analyses K̂'s pattern when it changed (a soft support's contact), counting and timing.
  void AnalyzeIfChanged(const SparseMatrix& hessian);
  // Factorises `hessian` (+ α M in free fall), regularising with growing multiples of M if
  // it is singular; returns the status of the last attempt and adds the attempts to
  // *factorizations.
  FactorizationStatus FactorizeNewtonMatrix(const BodyState& state, const Vertices& positions,
                                            bool free_fall, SparseMatrix* hessian,
                                            int* factorizations);

  const LayeredBody& body_;
  EquilibriumOptions options_;
  TotalPotential potential_;
  SparseCholesky cholesky_;
  std::vector<SupportPoint> hints_;
  TotalPotential::Evaluation last_;
  bool last_exact_ = false;
  int analyses_ = 0;  // symbolic analyses so far (EquilibriumResult::analyses)
  double analysis_seconds_ = 0;
  double body_size_ = 1;  // bounding-box diagonal of the rest body, m
};

}  // namespace ergo
