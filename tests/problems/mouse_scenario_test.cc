#include "problems/mouse_scenario.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/problems/scenario_checks.h"

namespace ergo {
namespace {

TEST(Problems, TwoBallMouseIsTheSmoothedUnionOfItsBalls) {
  const MouseShape shape;
  const TriMesh mouse = MakeTwoBallMouse(shape);
  ExpectValidSupport(mouse, "mouse");
  // Every vertex lies near the union's surface (Taubin moves it a little, most near the
  // crease), and the edges are near the requested length.
  double worst = 0;
  for (Eigen::Index v = 0; v < mouse.vertices.rows(); ++v) {
    const Eigen::Vector3d p = mouse.vertices.row(v).transpose();
    const double d = std::min((p - shape.rear.centre).norm() - shape.rear.radius,
                              (p - shape.front.centre).norm() - shape.front.radius);
    worst = std::max(worst, std::abs(d));
  }
  EXPECT_LT(worst, 0.3 * shape.edge_length);
  double edges = 0;
  for (Eigen::Index f = 0; f < mouse.triangles.rows(); ++f)
    edges += (mouse.vertices.row(mouse.triangles(f, 0)) - mouse.vertices.row(mouse.triangles(f, 1)))
                 .norm();
  EXPECT_NEAR(edges / mouse.triangles.rows(), shape.edge_length, 0.25 * shape.edge_length);
  // Concentric or disjoint balls are refused.
  MouseShape apart = shape;
  apart.front.centre.z() = 0.2;
  EXPECT_THROW(MakeTwoBallMouse(apart), InputError);
}

TEST(Problems, MouseQuickPresetBuildsAndTheHandRestsOnIt) {
  const MouseScenarioOptions options = MouseScenarioOptions::FromPreset("quick");
  ScenarioBuildReport report;
  const Scenario scenario = MakeMouseScenario(options, &report);
  std::cout << report.body << "\n" << report.support << "\n";
  ExpectValidSupport(scenario.support, "mouse");
  ExpectWellShapedSupport(scenario);
  ExpectWellShapedBody(*scenario.body);
  EXPECT_NEAR(scenario.body->total_mass(), options.hand.total_mass, 1e-9);
  EXPECT_EQ(scenario.body->lock().ToString(), "tx,tz,rx,ry,rz");
  // The designed part is the upper part of the mouse.
  for (Eigen::Index v = 0; v < scenario.support.vertices.rows(); ++v)
    EXPECT_EQ(scenario.design.active[v],
              scenario.support.vertices(v, 1) > options.designed_above_y);
  // k calibrated for 0.3 mm (0.296 mm measured).
  const EquilibriumResult result = ExpectBalancedEquilibrium(scenario, 2e-4, 4e-4);
  EXPECT_TRUE(result.state.rotation.isIdentity());
}

// A 5 mm negative image: contact spreads, so the penetration is below the neutral mouse's.
TEST(Problems, MouseNegativeImageIsAValidSupportTheHandRestsIn) {
  MouseScenarioOptions options = MouseScenarioOptions::FromPreset("quick");
  options.negative_image = true;
  ScenarioBuildReport report;
  const Scenario scenario = MakeMouseScenario(options, &report);
  std::cout << report.negative_image << "\n";
  ExpectValidSupport(scenario.support, "mouse negative image");
  ExpectWellShapedSupport(scenario);
  ExpectBalancedEquilibrium(scenario, 2e-5, 4e-4);
}

}  // namespace
}  // namespace ergo
