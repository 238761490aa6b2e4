// Tet quality measures (ergo/body/tet_quality.h) on tets whose answers are known.
#include <cmath>

#include <gtest/gtest.h>

#include "ergo/body/tet_quality.h"
#include "ergo/mesh/primitives.h"

namespace ergo {
namespace {

// Positively oriented: (v1 − v0)·((v2 − v0)×(v3 − v0)) > 0.
const Eigen::Vector3d kRegular[4] = {{1, 1, 1}, {-1, 1, -1}, {1, -1, -1}, {-1, -1, 1}};

TEST(Body, RegularTetHasRadiusRatioOneAndArccosOneThirdDihedrals) {
  EXPECT_NEAR(RadiusRatio(kRegular[0], kRegular[1], kRegular[2], kRegular[3]), 1.0, 1e-14);
  const double expected = std::acos(1.0 / 3.0) * 180 / 3.14159265358979323846;  // 70.53°
  for (double angle : DihedralAngles(kRegular[0], kRegular[1], kRegular[2], kRegular[3])) {
    EXPECT_NEAR(angle, expected, 1e-12);
  }
  // Swapping two corners inverts it: the ratio changes sign.
  EXPECT_NEAR(RadiusRatio(kRegular[1], kRegular[0], kRegular[2], kRegular[3]), -1.0, 1e-14);
}

TEST(Body, CornerTetAndSliverHaveTheirKnownQuality) {
  // The corner tet (0, e1, e2, e3): dihedral angles 90° at the three axes, and
  // arccos(1/√3) = 54.74° at the three slanted edges; r = 1/(3+√3), R = √3/2.
  const Eigen::Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::array<double, 6> angles = DihedralAngles(o, x, y, z);
  for (int e = 0; e < 3; ++e) EXPECT_NEAR(angles[e], 90.0, 1e-12);
  for (int e = 3; e < 6; ++e)
    EXPECT_NEAR(angles[e], std::acos(1 / std::sqrt(3.0)) * 180 / 3.14159265358979323846, 1e-12);
  EXPECT_NEAR(RadiusRatio(o, x, y, z), 3 * (1 / (3 + std::sqrt(3.0))) / (std::sqrt(3.0) / 2),
              1e-14);
  // A sliver: four nearly coplanar points on a square.
  const double h = 1e-3;
  EXPECT_LT(RadiusRatio({0, 0, 0}, {1, 0, h}, {1, 1, 0}, {0, 1, h}), 0.01);
  EXPECT_EQ(RadiusRatio(o, x, y, Eigen::Vector3d(1, 1, 0)), 0.0);  // flat
}

TEST(Body, MeasureTetQualityOfAKuhnGrid) {
  // Kuhn tets of a cube grid: all congruent, dihedral angles 45°, 60°, 90°.
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {2, 2, 2}, {2, 2, 2});
  const TetQuality q = MeasureTetQuality(grid);
  EXPECT_EQ(q.tet_count, 48);
  EXPECT_EQ(q.non_positive_count, 0);
  EXPECT_NEAR(q.min_dihedral_degrees, 45, 1e-12);
  EXPECT_NEAR(q.max_dihedral_degrees, 90, 1e-12);
  EXPECT_NEAR(q.min_radius_ratio, q.mean_radius_ratio, 1e-12);
  EXPECT_NEAR(q.min_volume, 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(q.min_edge_length, 1.0, 1e-14);
  EXPECT_NEAR(q.max_edge_length, std::sqrt(3.0), 1e-14);
}

}  // namespace
}  // namespace ergo
