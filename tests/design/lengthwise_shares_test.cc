// The load's split along a body's length (lengthwise_shares.h): hand-placed forces land in the
// bands of their rest positions, read from either end; and a body turned end for end on a flat
// slab splits its load the other way round.
#include "ergo/design/lengthwise_shares.h"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/body/core_lock.h"
#include "ergo/design/design_problem.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

// A 0.1 m cube (its core the hollowed middle) that only moves vertically.
LayeredBody Cube(int cells) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  return testing::MakeHollowCubeBody(0.1, cells, 1e4, 0.45, options, Eigen::Vector3d(0, 0.06, 0));
}

TEST(Design, LengthwiseSharesCountHandPlacedForcesInTheirRestBands) {
  const LayeredBody body = Cube(3);
  const Skin& skin = body.skin();
  const Vertices& rest = body.rest().vertices;
  // The skin's rest z runs over [−0.05, 0.05]: pick one vertex at each end and one in the middle.
  Eigen::Index back = -1, front = -1, middle = -1;
  for (Eigen::Index l = 0; l < skin.vertices.size(); ++l) {
    const double z = rest(skin.vertices[l], 2);
    if (back < 0 && std::abs(z + 0.05) < 1e-12) back = l;
    if (front < 0 && std::abs(z - 0.05) < 1e-12) front = l;
    if (middle < 0 && std::abs(z - (-0.05 + 0.1 / 3)) < 1e-9) middle = l;  // fraction 1/3
  }
  ASSERT_GE(back, 0);
  ASSERT_GE(front, 0);
  ASSERT_GE(middle, 0);
  SurfaceContacts contacts;
  contacts.skin_force = Vertices::Zero(skin.vertices.size(), 3);
  // Gravity pulls −y: upward pushes count by their y component (sideways parts do not).
  contacts.skin_force.row(back) = Eigen::RowVector3d(5, 1, 0);
  contacts.skin_force.row(middle) = Eigen::RowVector3d(0, 2, 7);
  contacts.skin_force.row(front) = Eigen::RowVector3d(0, 5, 0);
  // A pull away from the support presses nothing and is left out.
  Eigen::Index other = (front + 1) % skin.vertices.size();
  while (other == back || other == middle) other = (other + 1) % skin.vertices.size();
  contacts.skin_force.row(other) = Eigen::RowVector3d(0, -3, 0);
  const std::vector<double> ends = {0.3, 0.6, 1.0};
  const LengthwiseShares from_back = ComputeLengthwiseShares(body, contacts, ends, true);
  ASSERT_EQ(from_back.shares.size(), 3u);
  EXPECT_NEAR(from_back.normal_force, 8, 1e-12);
  // Fraction 0 → first band; 1/3 → the second ([0.3, 0.6)); 1 → the last, which includes 1.
  EXPECT_NEAR(from_back.shares[0], 1.0 / 8, 1e-12);
  EXPECT_NEAR(from_back.shares[1], 2.0 / 8, 1e-12);
  EXPECT_NEAR(from_back.shares[2], 5.0 / 8, 1e-12);
  // Read from the largest z, the ends swap and 1/3 becomes 2/3: the last band.
  const LengthwiseShares from_front = ComputeLengthwiseShares(body, contacts, ends, false);
  EXPECT_NEAR(from_front.shares[0], 5.0 / 8, 1e-12);
  EXPECT_NEAR(from_front.shares[1], 0, 1e-12);
  EXPECT_NEAR(from_front.shares[2], 3.0 / 8, 1e-12);
  // Nothing touching: no shares.
  contacts.skin_force.setZero();
  EXPECT_TRUE(ComputeLengthwiseShares(body, contacts, ends, true).shares.empty());
}

// The same cube turned half a turn about the vertical (its front becomes its back; a proper
// rotation, so the tet mesh turns with it) on a slab that the turn maps to itself: its
// equilibrium is the first one turned, so its split read from the back equals the first's read
// from the front, to the solver's tolerance. (The grid's tet split is not mirror-symmetric, so
// one cube alone need not split evenly: measured 0.227 against 0.203 on its two ends.) The
// whole weight is carried: Σ w = the load.
TEST(Design, ABodyTurnedEndForEndSplitsItsLoadTheOtherWayRound) {
  const TriMesh slab = MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {1, 1, 1});
  DesignOptions options;
  options.equilibrium.contact_stiffness = 4e6;
  // Band ends between the grid's rows (fractions k/6), so no row sits on an end.
  const std::vector<double> ends = {0.25, 0.75, 1.0};
  auto split = [&](const LayeredBody& body, bool from_min_z) {
    DesignProblem problem(body, slab, RestState(body), options);
    const DesignEvaluation at = problem.Evaluate(problem.InitialDesign(), false);
    EXPECT_TRUE(at.ok) << at.message;
    const LengthwiseShares out =
        ComputeLengthwiseShares(body, at.pressures.contacts, ends, from_min_z);
    EXPECT_NEAR(out.normal_force, body.TotalLoad().norm(), 1e-6 * body.TotalLoad().norm());
    return out.shares;
  };
  LayeredBodyOptions locked;
  locked.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  const Eigen::Matrix3d half_turn =
      Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const LayeredBody turned = testing::MakeHollowCubeBody(0.1, 6, 1e4, 0.45, locked,
                                                         Eigen::Vector3d(0, 0.06, 0), half_turn);
  const std::vector<double> front_first = split(Cube(6), false);
  const std::vector<double> turned_back_first = split(turned, true);
  ASSERT_EQ(front_first.size(), 3u);
  ASSERT_EQ(turned_back_first.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned_back_first[k], front_first[k], 1e-6) << k;
  EXPECT_GT(front_first[1], 0.3);  // the middle half's rows press too
  EXPECT_NEAR(front_first[0] + front_first[1] + front_first[2], 1.0, 1e-12);
}

}  // namespace
}  // namespace ergo
