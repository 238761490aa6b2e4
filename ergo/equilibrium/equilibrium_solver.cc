#include "ergo/equilibrium/equilibrium_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include <glog/logging.h>

#include "ergo/equilibrium/golden_section.h"
#include "ergo/mesh/preconditioned_cg.h"
#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

using Clock = std::chrono::steady_clock;

// Skin vertices that entered, left or changed feature between two contact sets (both
// ordered by point index).
struct ActiveSetChange {
  int entered = 0, left = 0, switched = 0;
};

ActiveSetChange CompareActiveSets(const ContactSet& before, const ContactSet& after) {
  ActiveSetChange change;
  size_t i = 0, j = 0;
  while (i < before.contacts.size() || j < after.contacts.size()) {
    if (j == after.contacts.size() ||
        (i < before.contacts.size() && before.contacts[i].point < after.contacts[j].point)) {
      ++change.left;
      ++i;
    } else if (i == before.contacts.size() || after.contacts[j].point < before.contacts[i].point) {
      ++change.entered;
      ++j;
    } else {
      if (before.contacts[i].anchor.feature != after.contacts[j].anchor.feature) ++change.switched;
      ++i;
      ++j;
    }
  }
  return change;
}

// Trace of the diagonal of an upper-triangular compressed matrix.
double DiagonalSum(const SparseMatrix& upper) {
  double sum = 0;
  for (int col = 0; col < upper.outerSize(); ++col) sum += upper.coeff(col, col);
  return sum;
}

}  // namespace

const char* EquilibriumStatusName(EquilibriumStatus status) {
  switch (status) {
    case EquilibriumStatus::kConverged:
      return "converged";
    case EquilibriumStatus::kStalled:
      return "converged (stalled)";
    case EquilibriumStatus::kIterationCap:
      return "iteration cap";
    case EquilibriumStatus::kLineSearchFailure:
      return "line search failure";
    case EquilibriumStatus::kNonFinite:
      return "non-finite values";
    case EquilibriumStatus::kNoContact:
      return "no contact";
    case EquilibriumStatus::kUnconstrained:
      return "unconstrained core DOF";
    case EquilibriumStatus::kInterrupted:
      return "interrupted";
  }
  return "unknown";
}

std::string EquilibriumResult::BriefReport() const {
  std::ostringstream out;
  out << EquilibriumStatusName(status) << ": " << iterations << " Newton iterations, residual "
      << residual << " N (" << relative_residual << " of the load), " << contact_vertices
      << " contact vertices (" << projected_steps << " projected steps), max penetration "
      << max_penetration * 1e3 << " mm, " << total_seconds << " s";
  if (!converged) out << " — " << message;
  return out.str();
}

std::string EquilibriumResult::FullReport() const {
  std::ostringstream out;
  out << BriefReport() << "\n"
      << "  energy " << energy << " J, contact force (" << contact_force.transpose() << ") N\n"
      << "  linear algebra: " << factorizations << " factorisations, " << pcg_iterations
      << " PCG iterations on reused factors, " << line_search_trials << " line-search trials"
      << (analyses > 0 ? ", " + std::to_string(analyses) + " symbolic analyses (" +
                             std::to_string(analysis_seconds) + " s)"
                       : "")
      << "\n"
      << "  active set: " << contacts_entered << " entered, " << contacts_left << " left, "
      << feature_switches << " feature switches\n"
      << "  time: assembly " << assembly_seconds << " s, contact " << contact_seconds
      << " s, factorisation " << factorization_seconds << " s, solves " << solve_seconds
      << " s, line search " << line_search_seconds << " s, total " << total_seconds << " s";
  return out.str();
}

EquilibriumSolver::EquilibriumSolver(const LayeredBody& body, const EquilibriumOptions& options,
                                     std::shared_ptr<const ElasticPart> soft_support)
    : body_(body),
      options_(options),
      potential_(body,
                 SurfaceContactOptions{options.contact_stiffness, options.contact_skin_share,
                                       options.contact_support_springs},
                 std::move(soft_support)) {
  CHECK_GT(options.relative_tolerance, 0.0);
  CHECK_GE(options.max_iterations, 1);
  CHECK_GE(options.stall_iterations, 0);
  CHECK_GT(options.free_fall_mass_scale, 0.0);
  // A rigid support's pattern is fixed: analyse it once here. A soft support's changes with
  // the contact set and is analysed at its first factorisation (AnalyzeIfChanged).
  if (!potential_.soft_support()) cholesky_.Analyze(potential_.system().pattern());
  const Vertices& rest = body.rest().vertices;
  body_size_ = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
}

FactorizationStatus EquilibriumSolver::FactorizeNewtonMatrix(const BodyState& state,
                                                             const Vertices& positions,
                                                             bool free_fall, SparseMatrix* hessian,
                                                             int* factorizations) {
  if (free_fall) potential_.AddScaledMass(options_.free_fall_mass_scale, state, positions, hessian);
  AnalyzeIfChanged(*hessian);
  FactorizationStatus factor = cholesky_.Factorize(*hessian);
  ++*factorizations;
  if (factor.ok) return factor;
  // Singular (e.g. a rotation not yet resisted): regularise with a growing multiple of M.
  double shift = 1e-10 * DiagonalSum(*hessian) / DiagonalSum(potential_.Mass(state, positions));
  for (int attempt = 0; attempt < 10 && !factor.ok; ++attempt, shift *= 100) {
    SparseMatrix shifted = *hessian;
    potential_.AddScaledMass(shift, state, positions, &shifted);
    factor = cholesky_.Factorize(shifted);
    ++*factorizations;
  }
  return factor;
}

void EquilibriumSolver::AnalyzeIfChanged(const SparseMatrix& hessian) {
  // A rigid support's pattern never changes (analysed in the constructor): no comparison of
  // index arrays in its Newton loop.
  if (!potential_.soft_support()) return;
  const Clock::time_point start = Clock::now();
  if (cholesky_.AnalyzeIfChanged(hessian)) {
    ++analyses_;
    analysis_seconds_ += SecondsSince(start);
  }
}

void EquilibriumSolver::set_contact_stiffness(double k) {
  options_.contact_stiffness = k;
  potential_.set_contact_stiffness(k);
}

std::string EquilibriumSolver::UnconstrainedTranslations(
    const TotalPotential::Evaluation& evaluation) const {
  // A rigid translation e moves every vertex by e; elasticity does not resist it, so its
  // stiffness is Σ eᵀ H_c e over the contact springs' point blocks.
  const ReducedLayout& layout = potential_.system().layout();
  const Eigen::Matrix3d stiffness = evaluation.contacts.TranslationStiffness();
  const double total = stiffness.trace();
  std::string free;
  constexpr const char* kNames[3] = {"tx", "ty", "tz"};
  for (int component : layout.core_components()) {
    if (component >= 3) continue;
    if (stiffness(component, component) <= 1e-9 * total) {
      if (!free.empty()) free += ", ";
      free += kNames[component];
    }
  }
  if (free.empty()) return "";
  return "the core translation " + free +
         " is free but every contact normal is perpendicular to it, so nothing resists "
         "sliding (frictionless contact); lock it (e.g. --lock=" +
         free + ")";
}

bool EquilibriumSolver::FellPastSupport(const Vertices& positions, const Support& support) const {
  const Eigen::Vector3d load = body_.TotalLoad();
  if (load.norm() == 0) return false;
  const Eigen::Vector3d down = load.normalized();
  const double body_top = (positions * down).minCoeff();
  const double support_bottom = (support.mesh().vertices * down).maxCoeff();
  return body_top > support_bottom;
}

EquilibriumResult EquilibriumSolver::Solve(const Support& support, const BodyState& start) {
  const Clock::time_point begin = Clock::now();
  EquilibriumResult result;
  result.state = start;
  BodyState& state = result.state;
  const int analyses_at_start = analyses_;
  const double analysis_seconds_at_start = analysis_seconds_;
  const Eigen::Index vertex_count = body_.rest().vertices.rows();
  if (static_cast<Eigen::Index>(hints_.size()) != vertex_count)
    hints_.assign(vertex_count, SupportPoint());
  const double load = body_.TotalLoad().norm();
  const double tolerance = options_.relative_tolerance * (load > 0 ? load : 1.0);
  const double stalled_tolerance = options_.stalled_relative_tolerance * (load > 0 ? load : 1.0);
  int iterations_within_stalled = 0;  // consecutive iterates with residual ≤ stalled_tolerance
  // Energy differences below this are round-off (the gravity potential dominates |E|).
  const double energy_scale =
      body_.total_mass() * body_.gravity().norm() * potential_.lever_length() +
      body_.options().external_force.norm() * potential_.lever_length();

  TotalPotential::Evaluation& e = last_;
  last_exact_ = false;
  ContactSet previous_skin;  // the skin's springs at the previous iterate
  ActiveSetChange change;
  const HessianKind first_kind =
      options_.exact_newton_first ? HessianKind::kExact : HessianKind::kProjectedPsd;
  auto evaluate = [&] {
    potential_.Evaluate(state, support, first_kind, true, &hints_, &e,
                        /*with_support_samples=*/false);
    last_exact_ = first_kind == HessianKind::kExact;
    result.assembly_seconds += e.assembly_seconds;
    result.contact_seconds += e.contact_seconds;
    result.residual = potential_.ResidualNorm(e.gradient);
    result.relative_residual = result.residual / (load > 0 ? load : 1.0);
    result.energy = e.energy;
    result.contact_vertices = e.contacts.skin_vertices_in_contact();
    result.contact_springs = e.contacts.springs();
    result.max_penetration = e.contacts.max_penetration;
    result.contact_force = e.contacts.TotalForceOnBody();
  };
  auto finish = [&](EquilibriumStatus status, const std::string& message) {
    // The one-way contact's score-only support samples, left out of the Newton iterations,
    // at the state returned (what the score and the pressures read).
    if (status != EquilibriumStatus::kInterrupted && e.positions.allFinite() &&
        e.positions.rows() > 0) {
      const double before = e.contact_seconds;
      potential_.AddSupportSamples(support, true, &e);
      result.contact_seconds += e.contact_seconds - before;
    }
    result.status = status;
    result.converged =
        status == EquilibriumStatus::kConverged || status == EquilibriumStatus::kStalled;
    result.analyses = analyses_ - analyses_at_start;
    result.analysis_seconds = analysis_seconds_ - analysis_seconds_at_start;
    result.message = message;
    result.total_seconds = SecondsSince(begin);
    return result;
  };
  for (int iteration = 0;; ++iteration) {
    if (options_.stop && options_.stop->load())
      return finish(EquilibriumStatus::kInterrupted, "interrupted");
    evaluate();
    result.iterations = iteration;
    change = CompareActiveSets(previous_skin, e.contacts.skin);
    result.contacts_entered += change.entered;
    result.contacts_left += change.left;
    result.feature_switches += change.switched;
    previous_skin.contacts.clear();
    for (const Contact& contact : e.contacts.skin.contacts) {
      previous_skin.contacts.emplace_back();
      previous_skin.contacts.back().point = contact.point;
      previous_skin.contacts.back().anchor.feature = contact.anchor.feature;
    }
    if (!std::isfinite(result.residual) || !std::isfinite(e.energy)) {
      return finish(EquilibriumStatus::kNonFinite,
                    "the energy or residual is not finite (an element inverted beyond repair, or "
                    "a non-finite input)");
    }
    // A free core DOF without stiffness makes the equilibrium non-unique (and K̂ singular
    // for the adjoint) even when its residual happens to vanish: check before accepting.
    if (e.contacts.springs() > 0) {
      const std::string unconstrained = UnconstrainedTranslations(e);
      if (!unconstrained.empty()) return finish(EquilibriumStatus::kUnconstrained, unconstrained);
    }
    if (result.residual <= tolerance) return finish(EquilibriumStatus::kConverged, "converged");
    iterations_within_stalled =
        result.residual <= stalled_tolerance ? iterations_within_stalled + 1 : 0;
    if (options_.stall_iterations > 0 && iterations_within_stalled >= options_.stall_iterations) {
      std::ostringstream message;
      message << "converged to " << result.relative_residual
              << " of the load (stalled: " << iterations_within_stalled << " iterations within "
              << options_.stalled_relative_tolerance << ", not " << options_.relative_tolerance
              << "; " << change.switched << " vertices switched features at the last)";
      return finish(EquilibriumStatus::kStalled, message.str());
    }
    if (iteration == options_.max_iterations) {
      return finish(EquilibriumStatus::kIterationCap,
                    "no convergence in " + std::to_string(iteration) + " Newton iterations");
    }
    const bool in_contact = e.contacts.springs() > 0;
    if (!in_contact && FellPastSupport(e.positions, support)) {
      return finish(EquilibriumStatus::kNoContact,
                    "no contact: the body fell past the support without touching it; place it "
                    "above the support (along the load) or check the support's position");
    }

    // Newton step. First conjugate gradients preconditioned by the last factor (cheap when
    // the matrix changed little), then a new factorisation: the exact K̂ if positive
    // definite, else the PSD projection.
    Eigen::VectorXd step;
    Clock::time_point mark = Clock::now();
    if (options_.reuse_factorization && cholesky_.factorized() &&
        first_kind == HessianKind::kExact) {
      SparseMatrix with_mass;
      const SparseMatrix* newton = &e.hessian();
      if (!in_contact) {
        with_mass = e.hessian();
        potential_.AddScaledMass(options_.free_fall_mass_scale, state, e.positions, &with_mass);
        newton = &with_mass;
      }
      // Forcing term ∝ the relative residual: superlinear convergence of the inexact Newton.
      const double forcing = std::clamp(result.relative_residual, 1e-12, 1e-2);
      const PcgResult cg = PreconditionedConjugateGradient(*newton, cholesky_, -e.gradient, forcing,
                                                           options_.max_pcg_iterations);
      result.pcg_iterations += cg.iterations;
      if (cg.converged) step = cg.x;
      result.solve_seconds += SecondsSince(mark);
    }
    if (step.size() == 0) {
      mark = Clock::now();
      bool exact_ok = false;
      if (first_kind == HessianKind::kExact) {
        SparseMatrix exact = e.hessian();
        if (!in_contact)
          potential_.AddScaledMass(options_.free_fall_mass_scale, state, e.positions, &exact);
        AnalyzeIfChanged(exact);
        exact_ok = cholesky_.Factorize(exact).ok;
        ++result.factorizations;
      }
      result.factorization_seconds += SecondsSince(mark);
      if (!exact_ok) {
        if (first_kind == HessianKind::kExact) {
          ++result.projected_steps;
          TotalPotential::Evaluation projected;
          potential_.Evaluate(state, support, HessianKind::kProjectedPsd, true, &hints_, &projected,
                              /*with_support_samples=*/false);
          result.assembly_seconds += projected.assembly_seconds;
          result.contact_seconds += projected.contact_seconds;
          e.hessian().swap(projected.hessian());
          last_exact_ = false;
        }
        mark = Clock::now();
        const FactorizationStatus factor = FactorizeNewtonMatrix(
            state, e.positions, !in_contact, &e.hessian(), &result.factorizations);
        result.factorization_seconds += SecondsSince(mark);
        if (!factor.ok) {
          return finish(EquilibriumStatus::kNonFinite,
                        "the Newton matrix could not be factorised: " + factor.message);
        }
      }
      mark = Clock::now();
      step = -cholesky_.Solve(e.gradient);
      result.solve_seconds += SecondsSince(mark);
    }
    // Shorten steps that would move a vertex farther than the cap (nearly free modes).
    const double cap = options_.max_step_fraction * body_size_;
    const double largest = potential_.LargestMove(state, e.positions, step);
    if (in_contact && largest > cap) step *= cap / largest;
    double free_fall_max_step = GoldenSectionOptions().max_step;
    if (!in_contact) {
      // In free fall no step may carry the skin past the support (a thin support would be
      // jumped): the largest vertex move is capped at the skin's clearance (sphere tracing),
      // plus a thousandth of the body's size to land in contact.
      const Clock::time_point start_clearance = Clock::now();
      double clearance = std::numeric_limits<double>::infinity();
      const Support& surface = potential_.ContactSurface(support);
      for (Eigen::Index l = 0; l < body_.skin().vertices.size(); ++l)
        clearance = std::min(
            clearance,
            std::sqrt(surface.ClosestPoint(e.positions.row(body_.skin().vertices[l]).transpose())
                          .squared_distance));
      const double move = potential_.LargestMove(state, e.positions, step);
      clearance += 1e-3 * body_size_;
      result.contact_seconds += SecondsSince(start_clearance);
      if (move > 0 && std::isfinite(clearance)) {
        if (move > clearance) {
          step *= clearance / move;  // land on the support, no farther
          free_fall_max_step = 1;
        } else {
          free_fall_max_step = clearance / move;
        }
      }
    }

    const double slope = e.gradient.dot(step);
    if (!step.allFinite() || !(slope < 0)) {
      return finish(EquilibriumStatus::kNonFinite,
                    "the Newton step is not finite or not a descent direction");
    }

    const Clock::time_point start_search = Clock::now();
    const double energy0 = e.energy;
    auto phi = [&](double eta) {
      return potential_.Energy(potential_.Retract(state, eta * step), support, &hints_) - energy0;
    };
    GoldenSectionOptions search;
    search.expand = !in_contact;
    search.max_step = free_fall_max_step;
    search.max_evaluations = options_.max_line_search_evaluations;
    search.noise = 1e-12 * (std::abs(energy0) + energy_scale);
    search.interpolate = options_.interpolated_line_search;
    const GoldenSectionResult found = GoldenSectionSearch(phi, slope, search);
    result.line_search_seconds += SecondsSince(start_search);
    result.line_search_trials += found.evaluations;
    if (found.step == 0) {
      std::ostringstream residual;  // %g: the residual is often far below 1e-6 N here
      residual << result.residual;
      return finish(EquilibriumStatus::kLineSearchFailure,
                    "no step length along the Newton direction lowered the energy (residual " +
                        residual.str() + " N)");
    }
    state = potential_.Retract(state, found.step * step);
    if (options_.progress) {
      NewtonIterationReport report;
      report.iteration = iteration;
      report.residual = result.residual;
      report.step = found.step;
      report.contact_vertices = result.contact_vertices;
      report.contacts_entered = change.entered;
      report.contacts_left = change.left;
      report.feature_switches = change.switched;
      options_.progress(report);
    }
  }
}

}  // namespace ergo
