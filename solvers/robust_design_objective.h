// RobustDesignObjective: the design objective averaged over several placements of the body
// (DESIGN.md §8, "robust to placement"; a sample-average objective as Jansen et al. 2013):
// φ_robust(x) = (1/K) Σ_p φ_p(x), where φ_p is the DesignProblem with the body's start pose
// moved by placement p (ergo/design/placement_checks.h) — each with its own equilibrium,
// warm starts and adjoint gradient, so ∇φ_robust is the mean of K exact gradients. The K
// evaluations run in parallel threads (the cores shared among them). A design that helps
// only where the body landed during the optimisation scores no better than its average.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ergo/design/design_problem.h"
#include "ergo/design/placement_checks.h"
#include "solvers/design_objective.h"
#include "solvers/objective.h"

namespace ergo {

class RobustDesignObjective : public Objective {
 public:
  // One problem per placement, copied from `problem` with its start pose moved (include a
  // zero placement for the centred pose). At least one placement.
  RobustDesignObjective(const DesignProblem& problem, const std::vector<Placement>& placements);
  RobustDesignObjective(const RobustDesignObjective& other);

  int NumParameters() const override { return problems_.front()->NumParameters(); }
  std::vector<std::string> TermNames() const override { return DesignTermNames(); }
  // Mean φ, its terms and ∇φ over the placements; fails (naming the placement) if any fails.
  // `seconds` is the wall time (the slowest placement), `timing` the sum of the placements'
  // splits (so its seconds exceed the wall time when they ran in parallel).
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  double LargestMove(const Eigen::VectorXd& dx) const override;
  double BoxHalfWidthForMove(double move) const override;
  double LengthScale() const override { return 1e-3; }
  std::string Describe() const override;

  int placement_count() const { return static_cast<int>(problems_.size()); }
  const std::vector<Placement>& placements() const { return placements_; }
  DesignProblem& problem(int p) { return *problems_[p]; }

 private:
  std::vector<Placement> placements_;
  std::vector<std::unique_ptr<DesignProblem>> problems_;
};

// The placements of a K-placement robust objective (K = 1, 3 or 5): the centred pose; for
// K = 3 also ±shift along the body's longer horizontal extent, for K = 5 along both
// horizontal axes (PlacementChecks without tilts). With tilt > 0 (rad), also the body held
// tilted by ±tilt about each axis whose rotation the lock holds (PlacementChecks' tilts: two
// more placements for the shoe and the chair, four for the mouse).
std::vector<Placement> RobustPlacements(const LayeredBody& body, int count, double shift,
                                        double tilt = 0);

}  // namespace ergo
