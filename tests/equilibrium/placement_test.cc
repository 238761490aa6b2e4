#include "ergo/equilibrium/placement.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

double MinSkinDistance(const LayeredBody& body, const BodyState& state, const Support& support,
                       bool* inside) {
  const Vertices positions = DeformedPositions(body, state);
  double nearest = INFINITY;
  *inside = false;
  for (Eigen::Index i = 0; i < body.skin().vertices.size(); ++i) {
    const Eigen::Vector3d p = positions.row(body.skin().vertices[i]);
    nearest = std::min(nearest, std::sqrt(support.ClosestPoint(p).squared_distance));
    *inside = *inside || support.Contains(p);
  }
  return nearest;
}

LayeredBody Cube() {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  return testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.5, 0));
}

TEST(Equilibrium, PlacementLeavesTheRequestedGapAboveTheSupport) {
  const LayeredBody body = Cube();
  const Support slab(MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {2, 1, 2}));
  const PlacementResult placed = PlaceAboveSupport(body, RestState(body), slab, 1e-3);
  ASSERT_TRUE(placed.found);
  bool inside = false;
  EXPECT_NEAR(MinSkinDistance(body, placed.state, slab, &inside), 1e-3, 1e-7);
  EXPECT_FALSE(inside);
  EXPECT_NEAR(placed.moved, 0.45 - 1e-3, 1e-7);  // bottom at y = 0.45 → 1 mm above y = 0
}

TEST(Equilibrium, PlacementDoesNotTunnelThroughAThinPlateFarBelow) {
  const LayeredBody body = Cube();
  const Support plate(MakeBox({-0.2, -3.001, -0.2}, {0.2, -3, 0.2}, {1, 1, 1}));  // 1 mm thick
  const PlacementResult placed = PlaceAboveSupport(body, RestState(body), plate, 5e-4);
  ASSERT_TRUE(placed.found);
  EXPECT_NEAR(placed.moved, 3.45 - 5e-4, 1e-6);
}

TEST(Equilibrium, PlacementLiftsABodyStartingInsideTheSupport) {
  const LayeredBody body = Cube();
  const Support slab(
      MakeBox({-0.2, -0.1, -0.2}, {0.2, 0.47, 0.2}, {2, 1, 2}));  // top cuts the cube
  const PlacementResult placed = PlaceAboveSupport(body, RestState(body), slab, 1e-3);
  ASSERT_TRUE(placed.found);
  EXPECT_NEAR(placed.moved, -0.02 - 1e-3, 1e-7);
}

TEST(Equilibrium, PlacementReportsASupportBesideTheBody) {
  const LayeredBody body = Cube();
  const Support aside(MakeBox({1, -0.1, 1}, {1.4, 0, 1.4}, {1, 1, 1}));
  EXPECT_FALSE(PlaceAboveSupport(body, RestState(body), aside, 1e-3).found);
}

}  // namespace
}  // namespace ergo
