// DesignObjective: a DesignProblem (paper §4: φ = ζ + γψ through the static equilibrium,
// adjoint gradient) seen as an Objective. Clone() is the DesignProblem copy constructor: an
// independent problem (own support, solver and warm-start cache, copied from this one) that
// shares the evaluation counters, so parallel probes start from this object's equilibria.
// Moves are the support parameterisation's vertex displacements, in metres.
#pragma once

#include <memory>
#include <string>

#include "ergo/design/design_problem.h"
#include "solvers/objective.h"

namespace ergo {

// A design evaluation's φ = ζ + γψ as named terms: "zeta" (weight 1) and "psi" (weight γ).
std::vector<std::string> DesignTermNames();
ObjectiveTerms DesignTerms(const DesignEvaluation& evaluation, double gamma);

class DesignObjective : public Objective {
 public:
  // Copies `problem` (which keeps a reference to its body: the body must outlive this).
  explicit DesignObjective(const DesignProblem& problem);

  int NumParameters() const override { return problem_->NumParameters(); }
  std::vector<std::string> TermNames() const override { return DesignTermNames(); }
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  // max over active vertices of SupportParameterization::VertexMoves(dx).
  double LargestMove(const Eigen::VectorXd& dx) const override;
  double BoxHalfWidthForMove(double move) const override;
  double LengthScale() const override { return 1e-3; }  // 1 mm
  std::string Describe() const override;

  DesignProblem& problem() { return *problem_; }
  const DesignProblem& problem() const { return *problem_; }
  // The full report of the most recent evaluation (pressures, equilibrium), for tools.
  const DesignEvaluation& last_evaluation() const { return last_; }

 private:
  std::unique_ptr<DesignProblem> problem_;
  DesignEvaluation last_;
};

}  // namespace ergo
