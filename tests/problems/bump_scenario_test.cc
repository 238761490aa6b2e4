#include "problems/bump_scenario.h"

#include <iostream>

#include <gtest/gtest.h>

#include "ergo/equilibrium/equilibrium_solver.h"

namespace ergo {
namespace {

TEST(Problems, BumpScenarioRestsOnTheBumpWithTheContactForceEqualToItsWeight) {
  const Scenario scenario = MakeBumpScenario();
  EquilibriumOptions options = scenario.design.equilibrium;
  if (getenv("VERBOSE"))
    options.progress = [](const NewtonIterationReport& r) {
      std::cout << "it " << r.iteration << " res " << r.residual << " eta " << r.step
                << " contacts " << r.contact_vertices << "\n";
    };
  EquilibriumSolver solver(*scenario.body, options);
  const EquilibriumResult result = solver.Solve(Support(scenario.support), scenario.start);
  ASSERT_TRUE(result.converged) << result.FullReport();
  const Eigen::Vector3d load = scenario.body->TotalLoad();
  // Only the vertical translation is free: the lock carries the bump's sideways push.
  EXPECT_LT(std::abs(result.contact_force.y() + load.y()), 1e-6 * load.norm());
  EXPECT_GT(result.contact_vertices, 3);
  std::cout << result.FullReport() << "\n"
            << scenario.body->rest().vertices.rows() << " body vertices\n";
}

}  // namespace
}  // namespace ergo
