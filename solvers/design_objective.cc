#include "solvers/design_objective.h"

#include <cmath>
#include <sstream>

namespace ergo {

std::vector<std::string> DesignTermNames() { return {"zeta", "psi"}; }

ObjectiveTerms DesignTerms(const DesignEvaluation& evaluation, double gamma) {
  return {{"zeta", 1, evaluation.zeta}, {"psi", gamma, evaluation.psi}};
}

DesignObjective::DesignObjective(const DesignProblem& problem)
    : problem_(std::make_unique<DesignProblem>(problem)) {}

ObjectiveValue DesignObjective::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  last_ = problem_->Evaluate(x, with_gradient);
  ObjectiveValue out;
  out.ok = last_.ok;
  out.message = last_.message;
  out.newton_iterations = last_.equilibrium.iterations;
  out.seconds = last_.timing.total_seconds;
  out.timing = last_.timing;
  if (!last_.ok) return out;
  out.phi = last_.phi;
  out.terms = DesignTerms(last_, problem_->options().gamma);
  if (with_gradient) out.gradient = last_.gradient;
  return out;
}

std::unique_ptr<Objective> DesignObjective::Clone() const {
  return std::make_unique<DesignObjective>(*problem_);
}

double DesignObjective::LargestMove(const Eigen::VectorXd& dx) const {
  const Eigen::VectorXd moves = problem_->parameterization().VertexMoves(dx);
  return moves.size() == 0 ? 0.0 : moves.maxCoeff();
}

double DesignObjective::BoxHalfWidthForMove(double move) const {
  return problem_->parameterization().BoxHalfWidthForMove(move);
}

std::string DesignObjective::Describe() const {
  const SupportParameterization& p = problem_->parameterization();
  std::ostringstream space;
  switch (p.kind()) {
    case DesignParameterization::kPositions:
      space << "positions";
      break;
    case DesignParameterization::kNormalDisplacement:
      space << "normal displacements";
      break;
    case DesignParameterization::kFiltered:
      space << "filtered normal displacements (radius " << 1e3 * p.filter_radius() << " mm"
            << (p.l2_metric() ? ", L² metric)" : ")");
      break;
    case DesignParameterization::kSpline:
      space << "cubic B-spline lattice (knot spacing " << 1e3 * p.filter_radius() << " mm, "
            << p.size() << " controls)";
      break;
  }
  std::ostringstream gamma;
  gamma << problem_->options().gamma;
  return std::to_string(p.active_vertices().size()) + " support vertices, " + space.str() +
         ", γ = " + gamma.str();
}

}  // namespace ergo
