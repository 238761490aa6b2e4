// FreshScoreObjective: the score a person gets on a design — the body placed afresh at each
// of a set of placements, φ averaged over them (MeanPlacedPhi) — as an Objective without a
// gradient, so that a population's fresh scores aggregate (and spread over processes) like
// its optimised objective. Evaluate(x, true) fails: no gradient is computed here.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "ergo/design/design_problem.h"
#include "ergo/design/placement_checks.h"
#include "solvers/design_objective.h"
#include "solvers/objective.h"

namespace ergo {

class FreshScoreObjective : public Objective {
 public:
  // Copies `problem` and places it afresh (warm starts cleared). `stop` (may be null) ends
  // a pending evaluation as failed.
  FreshScoreObjective(const DesignProblem& problem, std::vector<Placement> placements,
                      const std::atomic<bool>* stop = nullptr);

  int NumParameters() const override { return design_.NumParameters(); }
  // One term: φ placed afresh, averaged over the placements (its ζ and ψ are not kept).
  std::vector<std::string> TermNames() const override { return {"fresh_phi"}; }
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  double LargestMove(const Eigen::VectorXd& dx) const override { return design_.LargestMove(dx); }
  double BoxHalfWidthForMove(double move) const override {
    return design_.BoxHalfWidthForMove(move);
  }
  double LengthScale() const override { return design_.LengthScale(); }
  std::string Describe() const override;

 private:
  DesignObjective design_;  // the problem placed afresh; its design space
  std::vector<Placement> placements_;
  const std::atomic<bool>* stop_;
};

}  // namespace ergo
