// Placement checks: the moved start poses (rigid: shape kept, centre moved, rotation about
// the core centre), the checks' axes across the load and tilts about free rotation axes
// only, and a placed problem starting from the moved pose.
#include "ergo/design/placement_checks.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

LayeredBody Cube(const std::string& lock) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock(lock);
  return testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.06, 0));
}

// The cube above a flat slab, its equilibria started from `placement`.
DesignProblem CubeOnSlab(const LayeredBody& body, DesignPlacement placement) {
  const TriMesh slab = MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {4, 1, 4});
  DesignOptions options;
  options.equilibrium.contact_stiffness = 4e6;
  options.placement = placement;
  return DesignProblem(body, slab, RestState(body), options);
}

TEST(Design, MovedRigidlyKeepsTheShapeAndTurnsAboutTheCoreCentre) {
  const LayeredBody body = Cube("tx,tz");
  BodyState state = RestState(body);
  state.free_displacement.setConstant(1e-4);  // a deformed state
  const Eigen::Vector3d shift(0.003, 0, -0.002), tilt(0.02, 0, 0);
  const BodyState moved = MovedRigidly(body, state, shift, tilt);
  const Vertices before = DeformedPositions(body, state), after = DeformedPositions(body, moved);
  const Eigen::Matrix3d turn = RotationExp(tilt);
  for (Eigen::Index v = 0; v < before.rows(); ++v) {
    const Eigen::Vector3d expected =
        state.centre + turn * (before.row(v).transpose() - state.centre) + shift;
    EXPECT_LT((after.row(v).transpose() - expected).norm(), 1e-12) << "vertex " << v;
  }
  EXPECT_LT((moved.centre - state.centre - shift).norm(), 1e-15);
  EXPECT_LT((moved.torque_angle - tilt).norm(), 1e-15);
}

TEST(Design, PlacementChecksShiftAcrossTheLoadAndTiltAboutHeldAxesOnly) {
  const LayeredBody pitch_only = Cube("tx,tz,ry,rz");  // the shoe's lock: pitch about x free
  const std::vector<Placement> checks = PlacementChecks(pitch_only, 3e-3, M_PI / 180, true);
  ASSERT_EQ(checks.size(), 6u);
  const Eigen::Vector3d down = pitch_only.TotalLoad().normalized();
  int shifts = 0, tilts = 0;
  for (const Placement& p : checks) {
    if (!p.shift.isZero()) {
      ++shifts;
      EXPECT_NEAR(p.shift.norm(), 3e-3, 1e-15) << p.name;
      EXPECT_NEAR(p.shift.dot(down), 0, 1e-15) << p.name;
      EXPECT_TRUE(p.tilt.isZero()) << p.name;
    } else {
      ++tilts;  // the roll about z, held by the lock (y is the load: a yaw, no tilt)
      EXPECT_EQ(p.tilt.x(), 0);
      EXPECT_EQ(p.tilt.y(), 0);
      EXPECT_NEAR(std::abs(p.tilt.z()), M_PI / 180, 1e-15) << p.name;
    }
  }
  EXPECT_EQ(shifts, 4);
  EXPECT_EQ(tilts, 2);
  EXPECT_EQ(checks[0].name, "x+3mm");
  EXPECT_EQ(checks[4].name, "rz+1deg");
  // The tilts alone are the checks' tail; no angle, no tilts.
  const std::vector<Placement> held_tilts = HeldTilts(pitch_only, M_PI / 180);
  ASSERT_EQ(held_tilts.size(), 2u);
  EXPECT_EQ(held_tilts[1].name, checks[5].name);
  EXPECT_EQ(held_tilts[1].tilt, checks[5].tilt);
  EXPECT_TRUE(HeldTilts(pitch_only, 0).empty());
  // Rotations all held (the mouse): tilts about x and z; all free: shifts only.
  const std::vector<Placement> held = PlacementChecks(Cube("tx,tz,rx,ry,rz"), 3e-3, 0.01, true);
  ASSERT_EQ(held.size(), 8u);
  EXPECT_EQ(held[4].name, "rx+0.572958deg");
  EXPECT_EQ(held[6].tilt, Eigen::Vector3d(0, 0, 0.01));
  EXPECT_EQ(PlacementChecks(Cube("tx,tz"), 3e-3, M_PI / 180, true).size(), 4u);
  EXPECT_EQ(PlacementChecks(Cube("tx,tz,ry,rz"), 3e-3, M_PI / 180, false).size(), 4u);
}

// Why only held axes: placed afresh, a body tilted about its free pitch axis re-settles to the
// centred equilibrium and scores the same, while one tilted about a held axis stays turned by
// the tilt (the lock keeps it) and presses one edge harder.
TEST(Design, ATiltAboutAFreeAxisResettlesWhileTheLockKeepsAHeldOne) {
  const LayeredBody body = Cube("tx,tz,ry,rz");
  const DesignProblem problem = CubeOnSlab(body, DesignPlacement::kFresh);
  const Eigen::VectorXd x = problem.InitialDesign();
  auto placed = [&](const Eigen::Vector3d& tilt) {
    Placement placement;
    placement.tilt = tilt;
    DesignProblem moved = PlacedProblem(problem, placement);
    return moved.Evaluate(x, false);
  };
  const double degree = M_PI / 180;
  const DesignEvaluation centred = placed(Eigen::Vector3d::Zero());
  const DesignEvaluation free_tilt = placed(Eigen::Vector3d(degree, 0, 0));
  const DesignEvaluation held_tilt = placed(Eigen::Vector3d(0, 0, degree));
  ASSERT_TRUE(centred.ok && free_tilt.ok && held_tilt.ok)
      << centred.message << " / " << free_tilt.message << " / " << held_tilt.message;
  const Eigen::Matrix3d& level = centred.equilibrium.state.rotation;
  // Free pitch: back to the centred pose (to the solver's tolerance) and the same score.
  const Eigen::Matrix3d free_turn = free_tilt.equilibrium.state.rotation * level.transpose();
  EXPECT_LT(std::abs(std::atan2(free_turn(2, 1), free_turn(1, 1))), 1e-6);
  EXPECT_NEAR(free_tilt.phi, centred.phi, 1e-6 * centred.phi);
  // Held roll: the lock's pitch updates keep R = Rx(θ)·Rz(tilt), whose first row is Rz's
  // (cos, −sin, 0): still turned by exactly the tilt. The lower edge presses harder
  // (measured: φ 1.3 % above the centred one, 3.97e6 against 3.92e6).
  const Eigen::Matrix3d& held = held_tilt.equilibrium.state.rotation;
  EXPECT_NEAR(std::atan2(-held(0, 1), held(0, 0)), degree, 1e-12);
  EXPECT_NEAR(held(0, 2), 0, 1e-12);
  std::cout << "phi centred " << centred.phi << ", pitch +1 deg " << free_tilt.phi
            << ", roll +1 deg " << held_tilt.phi << "\n";
  EXPECT_GT(held_tilt.phi - centred.phi, 1e3 * std::abs(free_tilt.phi - centred.phi));
  EXPECT_GT(held_tilt.phi, 1.005 * centred.phi);
}

TEST(Design, APlacedProblemStartsFromTheMovedPose) {
  const LayeredBody body = Cube("tx,tz");
  const DesignProblem problem = CubeOnSlab(body, DesignPlacement::kFollowed);
  Placement placement;
  placement.shift = Eigen::Vector3d(0.003, 0, 0);
  const DesignProblem placed = PlacedProblem(problem, placement);
  EXPECT_EQ(placed.options().placement, DesignPlacement::kFresh);
  EXPECT_LT((placed.start().centre - problem.start().centre - placement.shift).norm(), 1e-15);
}

// A placement without equilibrium makes the mean NaN and says which placement failed and why:
// "beside" moves the cube 1 m sideways, off the 40 cm slab, so it falls past it.
TEST(Design, MeanPlacedPhiNamesThePlacementWithoutEquilibrium) {
  const LayeredBody body = Cube("tx,tz");
  const TriMesh slab = MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {4, 1, 4});
  DesignOptions options;
  options.equilibrium.contact_stiffness = 4e6;
  const DesignProblem problem(body, slab, RestState(body), options);
  Placement centred, beside;
  centred.name = "centred";
  beside.name = "beside";
  beside.shift = Eigen::Vector3d(1.0, 0, 0);
  const Eigen::VectorXd x = problem.InitialDesign();
  std::string failure = "stale";
  ASSERT_TRUE(std::isfinite(MeanPlacedPhi(problem, x, {centred}, nullptr, nullptr, &failure)));
  EXPECT_TRUE(failure.empty()) << failure;
  const double phi = MeanPlacedPhi(problem, x, {centred, beside}, nullptr, nullptr, &failure);
  EXPECT_TRUE(std::isnan(phi));
  EXPECT_EQ(failure.rfind("beside: ", 0), 0u) << failure;
  EXPECT_NE(failure.find("no contact"), std::string::npos) << failure;
}

}  // namespace
}  // namespace ergo
