#include "ergo/design/design_problem.h"

#include <chrono>
#include <cmath>
#include <limits>

#include <glog/logging.h>

#include "ergo/design/rest_shape_gradient.h"
#include "ergo/design/rigid_shape_gradient.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/ergonomics/pressure_score.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/preconditioned_cg.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

using Clock = std::chrono::steady_clock;

// The options with the contact's skin share fixed from the initial support (so that every
// design, and a fresh problem on the final design, uses the same contact model).
DesignOptions WithContactShare(const DesignOptions& options, const LayeredBody& body,
                               const TriMesh& support) {
  DesignOptions out = options;
  if (out.equilibrium.contact_skin_share == 0) {
    out.equilibrium.contact_skin_share =
        ContactSkinShare(body.skin().rest_areas, BarycentricVertexAreas(support), options.active);
  }
  return out;
}

}  // namespace

DesignProblem::DesignProblem(const LayeredBody& body, const TriMesh& support,
                             const BodyState& start, const DesignOptions& options)
    : body_(body),
      options_(WithContactShare(options, body, support)),
      initial_support_(support),
      parameterization_(support, options.active, options.parameterization, options.filter_radius,
                        options.l2_design_metric),
      support_laplacian_(UmbrellaLaplacian(support.triangles, support.vertices.rows())),
      support_(support, "support"),
      pressures_(body, support, options.pressure),
      solver_(body, options_.equilibrium, options.soft_support),
      start_(start),
      last_state_(start),
      counters_(std::make_shared<DesignCounters>()) {
  if (!options.soft_support) {
    adjoint_cholesky_.Analyze(solver_.potential().system().pattern());  // fixed pattern
    return;
  }
  // The foam: its boundary is the support mesh; designed = active boundary vertices off the
  // held base, fixed = the rest of the boundary and the base; the interior follows.
  const ElasticPart& part = *options.soft_support;
  const Eigen::VectorXi& surface_to_part = part.boundary().surface_to_tet;
  CHECK_EQ(surface_to_part.size(), support.vertices.rows())
      << "a soft support's problem takes its boundary at rest as the support mesh";
  const Eigen::Index n = part.rest().vertices.rows();
  rest_designed_.assign(static_cast<size_t>(n), false);
  std::vector<bool> fixed(static_cast<size_t>(n), false);
  for (Eigen::Index v = 0; v < n; ++v) fixed[v] = part.held()[v];
  for (Eigen::Index i = 0; i < surface_to_part.size(); ++i) {
    const int v = surface_to_part[i];
    const bool active = options.active.empty() || options.active[i];
    if (active && !part.held()[v]) {
      rest_designed_[v] = true;
    } else {
      fixed[v] = true;
    }
  }
  rest_extension_.emplace(part.rest(), rest_designed_, fixed);
}

DesignProblem::DesignProblem(const DesignProblem& other)
    : body_(other.body_),
      options_(other.options_),
      initial_support_(other.initial_support_),
      parameterization_(other.parameterization_),
      support_laplacian_(other.support_laplacian_),
      support_(other.support_),
      pressures_(other.pressures_),
      solver_(other.solver_),
      adjoint_cholesky_(other.adjoint_cholesky_),
      start_(other.start_),
      last_state_(other.last_state_),
      last_x_(other.last_x_),
      last_solve_ok_(other.last_solve_ok_),
      cache_(other.cache_),
      anchors_(other.anchors_),
      counters_(other.counters_),
      rest_designed_(other.rest_designed_),
      rest_extension_(other.rest_extension_) {}

void DesignProblem::set_contact_stiffness(double k) {
  options_.equilibrium.contact_stiffness = k;
  solver_.set_contact_stiffness(k);
}

TriMesh DesignProblem::SupportAt(const Eigen::VectorXd& x) const {
  return TriMesh{parameterization_.Positions(x), initial_support_.triangles};
}

void DesignProblem::set_start(const BodyState& start) {
  start_ = start;
  last_state_ = start;
  last_x_.resize(0);
  last_solve_ok_ = false;
  cache_.clear();
  anchors_.clear();
}

BodyState DesignProblem::FreshStart() const {
  const PlacementResult placed = PlaceAboveSupport(body_, start_, support_, options_.placement_gap);
  return placed.found ? placed.state : start_;
}

BodyState DesignProblem::WarmStart(const Eigen::VectorXd& x, bool* from_last) const {
  const BodyState* best = &last_state_;
  const Eigen::VectorXd* best_x = &last_x_;
  double nearest = last_x_.size() == x.size() ? (last_x_ - x).lpNorm<Eigen::Infinity>()
                                              : std::numeric_limits<double>::infinity();
  for (const auto& [cached_x, state] : cache_) {
    const double distance = (cached_x - x).lpNorm<Eigen::Infinity>();
    if (distance < nearest) {
      nearest = distance;
      best = &state;
      best_x = &cached_x;
    }
  }
  if (from_last) *from_last = best_x == &last_x_ || (*best_x == last_x_);
  return *best;
}

BodyState DesignProblem::TangentPrediction(const Eigen::VectorXd& x) const {
  const TotalPotential& potential = solver_.potential();
  const TotalPotential::Evaluation& e = solver_.last_evaluation();
  const TriMesh old_support{parameterization_.Positions(last_x_), initial_support_.triangles};
  const Vertices moved = parameterization_.Positions(x) - old_support.vertices;
  // Beyond half a millimetre the contact set changes and the tangent misleads Newton
  // (measured on the quick shoe: 1 mm steps 9 → 10 iterations, 3 mm 16 → 21).
  if (moved.rowwise().norm().maxCoeff() > 5e-4) return last_state_;
  // K̂ δy = −(∂G/∂x) δx at the last equilibrium, by conjugate gradients on the exact K̂ there
  // preconditioned with the last Newton factor.
  const Vertices change = ResidualShapeDerivative(e.contacts, body_, old_support, moved);
  const Eigen::VectorXd rhs =
      -potential.system().ReduceVertexGradient(last_state_, e.positions, change);
  if (!(rhs.squaredNorm() > 0)) return last_state_;
  const PcgResult cg =
      PreconditionedConjugateGradient(e.hessian(), solver_.factor(), rhs, 1e-6, 20);
  if (!cg.converged || !cg.x.allFinite()) return last_state_;
  const BodyState predicted = potential.Retract(last_state_, cg.x);
  const double predicted_energy = potential.Energy(predicted, support_);
  const double warm_energy = potential.Energy(last_state_, support_);
  return std::isfinite(predicted_energy) && predicted_energy < warm_energy ? predicted
                                                                           : last_state_;
}

void DesignProblem::Remember(const Eigen::VectorXd& x, const BodyState& state) {
  if (options_.warm_start_cache <= 0) return;
  if (static_cast<int>(cache_.size()) >= options_.warm_start_cache) cache_.erase(cache_.begin());
  cache_.emplace_back(x, state);
}

DesignEvaluation DesignProblem::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  const Clock::time_point begin = Clock::now();
  DesignEvaluation out;
  EvaluationTiming& timing = out.timing;
  CHECK_EQ(x.size(), NumParameters());
  auto finish = [&] {
    timing.total_seconds = SecondsSince(begin);
    counters_->nanoseconds += static_cast<long>(1e9 * timing.total_seconds);
  };
  auto fail = [&](const std::string& message) {
    out.ok = false;
    out.message = message;
    ++counters_->failures;
    finish();
    return out;
  };
  ++counters_->evaluations;
  if (!x.allFinite()) return fail("the design vector has non-finite entries");

  // Equilibrium on the support at x (Eq. 7–9).
  Clock::time_point mark = Clock::now();
  const Vertices support_positions = parameterization_.Positions(x);
  support_.UpdateVertices(support_positions);
  if (options_.soft_support) {
    // The foam's rest shape at x: its designed boundary where the design puts it, the
    // interior following.
    const ElasticPart& part = *options_.soft_support;
    const Eigen::VectorXi& surface_to_part = part.boundary().surface_to_tet;
    Vertices designed_move = Vertices::Zero(part.rest().vertices.rows(), 3);
    for (Eigen::Index i = 0; i < surface_to_part.size(); ++i)
      if (rest_designed_[surface_to_part[i]])
        designed_move.row(surface_to_part[i]) =
            support_positions.row(i) - initial_support_.vertices.row(i);
    try {
      out.soft_support = std::make_shared<const ElasticPart>(
          part.WithRestPositions(part.rest().vertices + rest_extension_->Extend(designed_move)));
      solver_.set_soft_support(out.soft_support);
    } catch (const InputError& error) {
      return fail(std::string("the design's rest shape cannot be used: ") + error.what());
    }
  }
  timing.support_seconds = SecondsSince(mark);
  // The start of the solve: placed afresh, warm from the nearest design, or one hop from the
  // nearest fresh anchor.
  mark = Clock::now();
  bool new_anchor = false, fresh = false, predict = false;
  BodyState solve_start;
  if (options_.placement == DesignPlacement::kFollowed) {
    // A path starts with the body placed afresh.
    bool from_last = false;
    fresh = cache_.empty();
    solve_start = fresh ? FreshStart() : WarmStart(x, &from_last);
    // (Not for a soft support: its rest shape, not a rigid surface, moves with the design.)
    predict = from_last && last_solve_ok_ && options_.tangent_predictor && !options_.soft_support &&
              solver_.last_hessian_exact() && solver_.factor().factorized();
  } else if (options_.placement == DesignPlacement::kFresh) {
    fresh = true;
    solve_start = FreshStart();
  } else {
    const std::pair<Eigen::VectorXd, BodyState>* nearest = nullptr;
    double distance = std::numeric_limits<double>::infinity();
    for (const auto& anchor : anchors_) {
      const double move = parameterization_.VertexMoves(x - anchor.first).maxCoeff();
      if (move < distance) {
        distance = move;
        nearest = &anchor;
      }
    }
    new_anchor = fresh = nearest == nullptr || distance > options_.anchor_move;
    solve_start = new_anchor ? FreshStart() : nearest->second;
  }
  timing.placement_seconds = SecondsSince(mark);
  timing.fresh_placements = fresh ? 1 : 0;
  if (predict) {
    mark = Clock::now();
    solve_start = TangentPrediction(x);
    timing.predictor_seconds = SecondsSince(mark);
  }
  out.equilibrium = solver_.Solve(support_, solve_start);
  const EquilibriumResult& solved = out.equilibrium;
  timing.equilibria = 1;
  timing.newton_iterations = solved.iterations;
  timing.factorizations = solved.factorizations;
  timing.pcg_iterations = solved.pcg_iterations;
  timing.line_search_trials = solved.line_search_trials;
  timing.contact_seconds = solved.contact_seconds;
  timing.assembly_seconds = solved.assembly_seconds;
  timing.factorization_seconds = solved.factorization_seconds;
  timing.solve_seconds = solved.solve_seconds;
  timing.line_search_seconds = solved.line_search_seconds;
  last_solve_ok_ = solved.converged;
  counters_->newton_iterations += solved.iterations;
  if (!solved.converged) return fail("equilibrium failed: " + solved.BriefReport());
  const BodyState& state = solved.state;
  Remember(x, state);
  last_x_ = x;
  if (new_anchor) {
    if (static_cast<int>(anchors_.size()) >= std::max(1, options_.warm_start_cache))
      anchors_.erase(anchors_.begin());
    anchors_.emplace_back(x, state);
  }
  last_state_ = state;

  // The contact forces the solver used, and the exact K̂ at y* for the adjoint.
  const TotalPotential& potential = solver_.potential();
  // Newton's last evaluation is at y* already (contacts, springs and, when Newton took the
  // exact K̂, the Hessian the adjoint needs): reuse it rather than assemble twice.
  TotalPotential::Evaluation computed;
  const bool reuse = !with_gradient || solver_.last_hessian_exact();
  if (!reuse) {
    mark = Clock::now();
    potential.Evaluate(state, support_, HessianKind::kExact, true, &solver_.hints(), &computed);
    timing.adjoint_seconds += SecondsSince(mark);
  }
  const TotalPotential::Evaluation& e = reuse ? solver_.last_evaluation() : computed;

  // Pressures of both surfaces from the springs the equilibrium used (Eq. 11–12, Fig. 4).
  mark = Clock::now();
  out.pressures = pressures_.Evaluate(e.contacts, support_.vertex_areas());
  timing.pressure_seconds = SecondsSince(mark);
  // ζ of them and, for the gradient, its explicit partials (timed with the adjoint that
  // chains them, as the time split documents).
  mark = Clock::now();
  const PressureScore score =
      ScorePressures(out.pressures, body_, options_.score_support_side, with_gradient);
  if (with_gradient) timing.adjoint_seconds += SecondsSince(mark);
  out.zeta_human = score.human;
  out.zeta_support = score.support;
  out.zeta = score.value;
  mark = Clock::now();
  const SmoothnessValue psi =
      EvaluateSmoothness(support_positions, support_laplacian_, options_.taubin);
  out.psi = psi.value;
  timing.psi_seconds = SecondsSince(mark);
  out.phi = out.zeta + options_.gamma * out.psi;
  if (!std::isfinite(out.phi)) return fail("the objective is not finite");

  if (with_gradient) {
    // dζ with respect to the support surface's vertices (the design's), then through the
    // design space.
    mark = Clock::now();
    Vertices d_support;
    if (options_.soft_support) {
      // dζ/dX at every deformed position fixed (rest_shape_gradient.h), pulled back through
      // the interior's extension to the designed boundary.
      const RestShapeGradient rest =
          SoftSupportRestGradient(potential, state, e, score, solver_.factor(), &adjoint_cholesky_);
      timing.adjoint_pcg_iterations += rest.pcg_iterations;
      timing.adjoint_factorizations += rest.factorizations;
      if (!rest.ok) {
        timing.adjoint_seconds += SecondsSince(mark);
        return fail(rest.message);
      }
      const Vertices designed = rest_extension_->PullBack(rest.gradient);
      const Eigen::VectorXi& surface_to_part = options_.soft_support->boundary().surface_to_tet;
      d_support.resize(surface_to_part.size(), 3);
      for (Eigen::Index i = 0; i < surface_to_part.size(); ++i)
        d_support.row(i) = designed.row(surface_to_part[i]);
    } else {
      // The adjoint through the rigid support's surface (rigid_shape_gradient.h).
      const TriMesh support_mesh{support_positions, initial_support_.triangles};
      const RigidShapeGradient rigid =
          RigidSupportShapeGradient(potential, state, e, out.pressures, score, support_mesh,
                                    solver_.factor(), &adjoint_cholesky_);
      timing.adjoint_pcg_iterations += rigid.pcg_iterations;
      timing.adjoint_factorizations += rigid.factorizations;
      if (!rigid.ok) {
        timing.adjoint_seconds += SecondsSince(mark);
        return fail(rigid.message);
      }
      d_support = rigid.gradient;
    }
    out.zeta_gradient = parameterization_.PullBack(d_support);
    timing.adjoint_seconds += SecondsSince(mark);
    mark = Clock::now();
    out.psi_gradient = parameterization_.PullBack(psi.gradient);
    timing.psi_seconds += SecondsSince(mark);
    out.gradient = out.zeta_gradient + options_.gamma * out.psi_gradient;
    ++counters_->gradients;
  }
  out.ok = true;
  out.message = "ok";
  finish();
  return out;
}

double AutoGamma(DesignProblem& problem, int power_of_ten, std::string* message) {
  const DesignEvaluation at = problem.Evaluate(problem.InitialDesign(), false);
  if (!at.ok) {
    if (message) *message = "cannot choose γ automatically: " + at.message;
    return -1;
  }
  return AutoGammaFrom(at, power_of_ten, message);
}

double AutoGammaFrom(const DesignEvaluation& at, int power_of_ten, std::string* message) {
  CHECK(at.ok);
  if (!(at.psi > 0)) {
    if (message)
      *message =
          "cannot choose γ automatically: ψ(x₀) = 0 (the initial support is Taubin-invariant); "
          "give γ explicitly";
    return -1;
  }
  const double kappa = at.zeta / at.psi;
  if (message)
    *message = "γ = κ·10^" + std::to_string(power_of_ten) +
               " with κ = ζ(x₀)/ψ(x₀) = " + std::to_string(kappa);
  return kappa * std::pow(10.0, power_of_ten);
}

const char* DesignPlacementName(DesignPlacement placement) {
  switch (placement) {
    case DesignPlacement::kFresh:
      return "fresh";
    case DesignPlacement::kFollowed:
      return "followed";
    case DesignPlacement::kAnchored:
      return "anchored";
  }
  return "?";
}

bool ParseDesignPlacement(const std::string& name, DesignPlacement* placement) {
  for (DesignPlacement candidate :
       {DesignPlacement::kFresh, DesignPlacement::kFollowed, DesignPlacement::kAnchored}) {
    if (name == DesignPlacementName(candidate)) {
      *placement = candidate;
      return true;
    }
  }
  return false;
}

}  // namespace ergo
