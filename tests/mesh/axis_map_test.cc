#include "ergo/mesh/axis_map.h"

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

// The FIND foot scan has z up and its length along x: "y,z,x" must put its z on ergo's y
// (up) and its x on ergo's z (the length), as a rotation.
TEST(Mesh, AxisMapTakesEachErgoAxisFromTheNamedInputAxis) {
  const Eigen::Matrix3d r = ParseAxisMap("y,z,x", "--axes");
  EXPECT_DOUBLE_EQ(r.determinant(), 1.0);
  Vertices p(1, 3);
  p << 1, 2, 3;  // input x, y, z
  ApplyAxisMap(r, &p);
  EXPECT_DOUBLE_EQ(p(0, 0), 2);  // ergo x = input y
  EXPECT_DOUBLE_EQ(p(0, 1), 3);  // ergo y = input z
  EXPECT_DOUBLE_EQ(p(0, 2), 1);  // ergo z = input x
  const Eigen::Matrix3d flipped = ParseAxisMap("-x,y,-z", "--axes");
  Vertices q(1, 3);
  q << 1, 2, 3;
  ApplyAxisMap(flipped, &q);
  EXPECT_DOUBLE_EQ(q(0, 0), -1);
  EXPECT_DOUBLE_EQ(q(0, 2), -3);
  EXPECT_TRUE(ParseAxisMap("x,y,z", "--axes").isIdentity());
}

TEST(Mesh, AxisMapRefusesMirrorsRepeatsAndUnknownAxes) {
  for (const char* bad : {"x,z,y", "-x,y,z", "x,x,z", "x,y", "x,y,w", "x,y,z,x", ""}) {
    try {
      ParseAxisMap(bad, "--axes");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--axes") << bad;
      EXPECT_FALSE(e.fix().empty()) << bad;
    }
  }
}

}  // namespace
}  // namespace ergo
