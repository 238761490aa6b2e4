#include "problems/shoe_scenario.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tests/problems/scenario_checks.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// Pitch of a rotation about x (positive tips the toes, +z, down).
double Pitch(const Eigen::Matrix3d& rotation) {
  return std::atan2(-rotation(1, 2), rotation(1, 1));
}

TEST(Problems, ShoeQuickPresetBuildsAndCarriesHalfTheBodyWeight) {
  const ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  ScenarioBuildReport report;
  const Scenario scenario = MakeShoeScenario(options, &report);
  std::cout << report.body << "\n" << report.support << "\n";
  ExpectValidSupport(scenario.support, "shoe sole");
  ExpectWellShapedSupport(scenario);
  ExpectWellShapedBody(*scenario.body);
  // Load: the foot's weight plus half of a 75 kg adult's.
  const Eigen::Vector3d load = scenario.body->TotalLoad();
  EXPECT_NEAR(load.y(), -(scenario.body->total_mass() + 37.5) * 9.81, 1e-9);
  // Plantar layer 1–2 cm, the top at least half an edge length (meshable).
  EXPECT_GE(report.layer.min_thickness, 0.5 * options.body_edge_length);
  // The sole is sized to the foot: its top covers the foot's outline with the margin.
  const Eigen::RowVector3d foot_lo = scenario.body->rest().vertices.colwise().minCoeff();
  const Eigen::RowVector3d foot_hi = scenario.body->rest().vertices.colwise().maxCoeff();
  const Eigen::RowVector3d sole_lo = scenario.support.vertices.colwise().minCoeff();
  const Eigen::RowVector3d sole_hi = scenario.support.vertices.colwise().maxCoeff();
  for (int axis : {0, 2}) {
    EXPECT_NEAR(foot_lo[axis] - sole_lo[axis], options.sole_margin, 1e-9);
    EXPECT_NEAR(sole_hi[axis] - foot_hi[axis], options.sole_margin, 1e-9);
  }
  EXPECT_NEAR(sole_hi.y() - sole_lo.y(), options.sole_thickness, 1e-12);
  // Vertical translation and pitch only.
  EXPECT_EQ(scenario.body->lock().ToString(), "tx,tz,ry,rz");
  // k calibrated for 0.3 mm (0.29 mm measured).
  ExpectBalancedEquilibrium(scenario, 2e-4, 4e-4);
}

// Leaning forward (a positive torque about x) shifts the load to the forefoot: the foot
// pitches toes-down relative to standing upright, and the torque is balanced by contact.
TEST(Problems, ShoeLeanTorquePitchesTheFootForward) {
  if (testing::SanitizedBuild())
    GTEST_SKIP() << "two quick-shoe equilibria take over a minute under the sanitizers; the shoe "
                    "preset test runs the same code";
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  const Scenario upright = MakeShoeScenario(options);
  options.lean_torque = 8;  // N·m: the centre of mass ~2 cm ahead of the core
  const Scenario leaning = MakeShoeScenario(options);
  // The lean adds to the load point's torque (quiet standing's 0.445 by default).
  EXPECT_DOUBLE_EQ(
      leaning.body->options().external_torque.x() - upright.body->options().external_torque.x(),
      8.0);
  const EquilibriumResult a = ExpectBalancedEquilibrium(upright, 1e-5, 1e-3);
  const EquilibriumResult b = ExpectBalancedEquilibrium(leaning, 1e-5, 1e-3);
  std::cout << "pitch upright " << Pitch(a.state.rotation) << " rad, leaning "
            << Pitch(b.state.rotation) << " rad\n";
  EXPECT_GT(Pitch(b.state.rotation), Pitch(a.state.rotation) + 1e-3);
}

TEST(Problems, ShoeNegativeImageMustNotCutThroughTheSole) {
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  options.negative_image = true;
  options.negative.depth = options.sole_thickness;
  EXPECT_THROW(MakeShoeScenario(options), InputError);
  EXPECT_THROW(ShoeScenarioOptions::FromPreset("slow"), InputError);
}

}  // namespace
}  // namespace ergo
