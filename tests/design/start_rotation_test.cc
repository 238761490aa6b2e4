// StaticEquilibriumOptions::start_rotation (ergo_simulate --roll): the rest body is turned about
// its core's centre before it is placed, and a lock on that rotation holds it there.
#include <cmath>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/design/centre_of_pressure.h"
#include "ergo/design/static_equilibrium.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

// Known answer: a 10 cm cube of stiff tissue (E = 1 MPa, 20 N on it) turned 10 degrees about z
// and lowered with only its height free stands on its lowest edge, at
// x = 5 cm · (sin 10° − cos 10°) = −40.6 mm from its centre; level, it stands on its face,
// centred. Measured: −41.3 mm, the squeezed edge bulging outwards; 2 mm allows for that and
// the contact's spread, a twentieth of the 40 mm a missing turn would leave.
TEST(StartRotation, ACubeTurnedAboutItsLengthStandsOnItsLowestEdge) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  options.external_force = Eigen::Vector3d(0, -20, 0);
  const LayeredBody body =
      testing::MakeHollowCubeBody(0.1, 9, 1e6, 0.45, options, Eigen::Vector3d(0, 0.08, 0));
  const TriMesh block = MakeBox(Eigen::Vector3d(-0.1, -0.04, -0.1), Eigen::Vector3d(0.1, 0, 0.1),
                                Eigen::Vector3i(8, 2, 8));
  StaticEquilibriumOptions solve;
  solve.contact_stiffness = 1e8;
  const StaticEquilibrium level = SolveStaticEquilibrium(body, block, "block", solve);
  ASSERT_TRUE(level.ok()) << level.message();
  EXPECT_NEAR(ComputeCentreOfPressure(body, level.result.state, level.pressures.contacts).point.x(),
              0, 1e-3);

  const double roll = 10 * M_PI / 180;
  solve.start_rotation = Eigen::Vector3d(0, 0, roll);
  const StaticEquilibrium turned = SolveStaticEquilibrium(body, block, "block", solve);
  ASSERT_TRUE(turned.ok()) << turned.message();
  EXPECT_TRUE(turned.result.state.rotation.isApprox(RotationExp(solve.start_rotation), 1e-12));
  const double edge = 0.05 * (std::sin(roll) - std::cos(roll));
  const double x =
      ComputeCentreOfPressure(body, turned.result.state, turned.pressures.contacts).point.x();
  EXPECT_NEAR(x, edge, 0.002);

  solve.start_rotation = Eigen::Vector3d(0, 0, NAN);
  EXPECT_THROW(SolveStaticEquilibrium(body, block, "block", solve), InputError);
}

}  // namespace
}  // namespace ergo
