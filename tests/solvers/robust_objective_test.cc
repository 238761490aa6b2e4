// The placement-averaged objective (solvers/robust_design_objective.h) on the ball-on-bump
// scene: its value and gradient are the mean of the placed problems' own, its gradient agrees
// with central differences (along itself and a random direction), and copies evaluated in
// parallel agree with the original.
#include "solvers/robust_design_objective.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "problems/bump_scenario.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// Central differences of the mean along its own gradient and a random direction (fresh
// solves are deterministic: differences of 1e-7 m stay within one contact configuration).
void ExpectGradientMatchesDifferences(RobustDesignObjective& robust, const Eigen::VectorXd& x0,
                                      const Eigen::VectorXd& gradient, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd random(x0.size());
  for (Eigen::Index i = 0; i < random.size(); ++i) random[i] = normal(rng);
  for (const Eigen::VectorXd& d :
       {Eigen::VectorXd(gradient.normalized()), Eigen::VectorXd(random.normalized())}) {
    double best = INFINITY;
    for (double h : {1e-6, 1e-7, 1e-8}) {
      const double fd =
          (robust.Evaluate(x0 + h * d, false).phi - robust.Evaluate(x0 - h * d, false).phi) /
          (2 * h);
      best = std::min(best, std::abs(fd - gradient.dot(d)) /
                                std::max(std::abs(gradient.dot(d)), 1e-3 * gradient.norm()));
    }
    EXPECT_LT(best, 1e-4);
  }
}

TEST(Solvers, RobustObjectiveIsTheMeanOverPlacementsAndItsGradientMatchesDifferences) {
  if (testing::SanitizedBuild())
    GTEST_SKIP() << "finite differences over five placements take minutes under the sanitizers; "
                    "the design gradient tests run the same adjoint";
  BumpScenarioOptions options;
  options.edge_length = 0.016;
  Scenario scenario = MakeBumpScenario(options);
  scenario.design.equilibrium.relative_tolerance = 1e-11;
  scenario.design.placement = DesignPlacement::kFresh;  // deterministic per design
  const DesignProblem problem = scenario.MakeProblem();
  const std::vector<Placement> placements = RobustPlacements(*scenario.body, 3, 2e-3);
  ASSERT_EQ(placements.size(), 3u);
  RobustDesignObjective robust(problem, placements);
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const ObjectiveValue at = robust.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;

  // The mean of the three placed problems, each evaluated on its own.
  double mean = 0, mean_zeta = 0, mean_psi = 0;
  long newton = 0;
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x0.size());
  for (const Placement& placement : placements) {
    DesignProblem placed = PlacedProblem(problem, placement);
    const DesignEvaluation e = placed.Evaluate(x0, true);
    ASSERT_TRUE(e.ok) << placement.name << ": " << e.message;
    mean += e.phi / 3;
    mean_zeta += e.zeta / 3;
    mean_psi += e.psi / 3;
    gradient += e.gradient / 3;
    newton += e.equilibrium.iterations;
  }
  EXPECT_NEAR(at.phi, mean, 1e-12 * mean);
  // Its named terms are the placements' means, weighted as in φ = ζ + γψ.
  ASSERT_EQ(robust.TermNames(), (std::vector<std::string>{"zeta", "psi"}));
  ASSERT_EQ(at.terms.size(), 2u);
  EXPECT_NEAR(TermValue(at.terms, "zeta"), mean_zeta, 1e-12 * mean_zeta);
  EXPECT_NEAR(TermValue(at.terms, "psi"), mean_psi, 1e-12 * std::abs(mean_psi) + 1e-300);
  EXPECT_EQ(at.terms[1].weight, problem.options().gamma);
  EXPECT_NEAR(at.terms[0].weight * at.terms[0].value + at.terms[1].weight * at.terms[1].value,
              at.phi, 1e-12 * at.phi);
  EXPECT_LT((at.gradient - gradient).norm(), 1e-9 * gradient.norm());
  // Its time split is the sum of the placements' (wall time: the slowest of them).
  EXPECT_EQ(at.timing.equilibria, 3);
  EXPECT_EQ(at.timing.fresh_placements, 3);
  EXPECT_EQ(at.timing.newton_iterations, newton);
  EXPECT_GE(at.timing.total_seconds, at.seconds);
  // The off-centre placements see the bump elsewhere: the mean is not the centred value.
  DesignProblem centred(problem);
  EXPECT_GT(std::abs(centred.Evaluate(x0, false).phi - at.phi), 1e-3 * at.phi);

  ExpectGradientMatchesDifferences(robust, x0, at.gradient, 2);

  // A clone evaluates the same (its placements run in parallel threads).
  std::unique_ptr<Objective> clone = robust.Clone();
  const ObjectiveValue again = clone->Evaluate(x0, true);
  EXPECT_NEAR(again.phi, at.phi, 1e-12 * at.phi);
}

// On a followed path every placement follows its own (only each one's first equilibrium is
// placed afresh): the off-centre placements once placed afresh at every evaluation, five
// cold solves where four warm ones do (the paper chair: 30–60 s per evaluation).
TEST(Solvers, RobustObjectiveFollowsEachPlacementsPathWhenTheProblemFollows) {
  BumpScenarioOptions options;
  options.edge_length = 0.016;
  Scenario scenario = MakeBumpScenario(options);
  scenario.design.placement = DesignPlacement::kFollowed;
  const DesignProblem problem = scenario.MakeProblem();
  RobustDesignObjective robust(problem, RobustPlacements(*scenario.body, 3, 2e-3));
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const ObjectiveValue first = robust.Evaluate(x0, true);
  ASSERT_TRUE(first.ok) << first.message;
  EXPECT_EQ(first.timing.fresh_placements, 3);
  const double largest = robust.LargestMove(first.gradient);
  const ObjectiveValue second = robust.Evaluate(x0 - first.gradient * (1e-4 / largest), true);
  ASSERT_TRUE(second.ok) << second.message;
  EXPECT_EQ(second.timing.fresh_placements, 0);
  EXPECT_LT(second.phi, first.phi);  // a 0.1 mm step down the gradient
}

// With --robust_tilt_deg the body is also held tilted about the axes its lock holds (the bump
// scene's ball: x and z; y is the load). Each tilt is one more placement after the shifts,
// and the mean's gradient still matches central differences: a tilted start is a start pose
// like a shifted one, its held rotation fixed through the equilibrium and the adjoint.
TEST(Solvers, RobustObjectiveWithHeldTiltsAveragesThemAndItsGradientMatchesDifferences) {
  if (testing::SanitizedBuild())
    GTEST_SKIP() << "finite differences over five placements take minutes under the sanitizers";
  BumpScenarioOptions options;
  options.edge_length = 0.016;
  Scenario scenario = MakeBumpScenario(options);
  scenario.design.equilibrium.relative_tolerance = 1e-11;
  scenario.design.placement = DesignPlacement::kFresh;
  const double tilt = 2 * M_PI / 180;
  const LayeredBody& body = *scenario.body;
  EXPECT_EQ(RobustPlacements(body, 5, 2e-3, tilt).size(), 9u);
  EXPECT_EQ(RobustPlacements(body, 3, 2e-3, tilt).size(), 7u);
  const std::vector<Placement> placements = RobustPlacements(body, 1, 2e-3, tilt);
  ASSERT_EQ(placements.size(), 5u);
  const char* names[] = {"centred", "rx+2deg", "rx-2deg", "rz+2deg", "rz-2deg"};
  for (int p = 0; p < 5; ++p) {
    EXPECT_EQ(placements[p].name, names[p]);
    EXPECT_TRUE(placements[p].shift.isZero()) << names[p];
  }
  EXPECT_EQ(placements[3].tilt, Eigen::Vector3d(0, 0, tilt));

  const DesignProblem problem = scenario.MakeProblem();
  RobustDesignObjective robust(problem, placements);
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const ObjectiveValue at = robust.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  double mean = 0;
  std::vector<double> phi;
  for (const Placement& placement : placements) {
    DesignProblem placed = PlacedProblem(problem, placement);
    const DesignEvaluation e = placed.Evaluate(x0, false);
    ASSERT_TRUE(e.ok) << placement.name << ": " << e.message;
    // The held tilt stays: the ball's core ends turned by exactly the placement's tilt.
    const Eigen::Matrix3d turn = RotationExp(placement.tilt) * problem.start().rotation;
    EXPECT_LT((e.equilibrium.state.rotation - turn).norm(), 1e-12) << placement.name;
    phi.push_back(e.phi);
    mean += e.phi / 5;
  }
  EXPECT_NEAR(at.phi, mean, 1e-12 * mean);
  // A 2° tilt moves the ball's contact on the bump: each tilted φ differs from the centred.
  for (int p = 1; p < 5; ++p) EXPECT_GT(std::abs(phi[p] - phi[0]), 1e-3 * phi[0]) << names[p];

  ExpectGradientMatchesDifferences(robust, x0, at.gradient, 3);
}
}  // namespace
}  // namespace ergo
