// What a plate reads under maps whose answers are known by hand: a field linear along x over a
// flat square, where each cell's mean is the field at the cell's centre, so the plate's force is
// the field's integral and its peak is the field at the centre of the best-placed cell.
#include "ergo/ergonomics/plate_reading.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/surface_geometry.h"
#include "tests/support/flat_grid.h"

namespace ergo {
namespace {

constexpr double kBase = 10e3;  // a, Pa
constexpr double kSlope = 1e6;  // b, Pa/m (1 kPa per mm)

// p = a + b x over the square [−half_width, half_width]² (the support's top, facing up).
PlanarPressureMap LinearMap(double half_width) {
  const TriMesh grid = testing::MakeFlatGrid(half_width, 4);
  Eigen::VectorXd pressure(grid.vertices.rows());
  for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v)
    pressure[v] = kBase + kSlope * grid.vertices(v, 0);
  return PlanarPressureMap::FromSurface(grid, pressure, BarycentricVertexAreas(grid),
                                        PlanarPressureMap::Facing::kUp);
}

TEST(PlateReading, APlateAlignedWithTheMapReadsItsForce) {
  // 20 mm square, 5 mm cells from its corner: four whole cells a side, each the field's mean,
  // so Σ p h² is the integral a·L² (the slope's part cancels over the symmetric square); the
  // margin's cells read nothing. The midpoint rule is exact for a linear field.
  const PlanarPressureMap map = LinearMap(0.01);
  const PressureGrid plate = ReadOnCoveringPlate(map, 0.005, Eigen::Vector2d::Zero(), 2, 4);
  EXPECT_EQ(plate.rows(), 8);
  EXPECT_EQ(plate.columns(), 8);
  EXPECT_NEAR(plate.TotalForce(), kBase * 0.02 * 0.02, 1e-12);
  EXPECT_NEAR(plate.pressure(2, 5), kBase + kSlope * 0.0075, 1e-6);  // centre x = 7.5 mm
  EXPECT_EQ(plate.pressure(0, 0), 0);
}

TEST(PlateReading, ThePeakIsTheFieldAtTheBestPlacedWholeCellsCentre) {
  // A 22 mm square under 5 mm cells offset by 0, 5/3 and 10/3 mm from its lower edge: the last
  // whole cells end at 9, 7.33 and 10.67 mm, so the best sits at 5.67–10.67 mm and reads the
  // field at its centre, 8.17 mm: 18.17 kPa. The cells cut by the edge read less (at most
  // 2/5 of 20 kPa), and no cell exceeds the field's largest value, 21 kPa.
  const PlanarPressureMap map = LinearMap(0.011);
  const PlatePeak peak = ComputePlatePeak(map, {0.005, 3, 4});
  const double centre = -0.011 - 2 * 0.005 / 3 + 4.5 * 0.005;  // the fifth cell of phase 2
  EXPECT_NEAR(peak.pressure, kBase + kSlope * centre, 1e-6);
  EXPECT_NEAR(peak.point.x(), centre, 1e-12);
  EXPECT_LE(peak.pressure, map.sample_pressure().maxCoeff());
  // One phase only: the cells from the edge, the best whole one centred at 6.5 mm.
  EXPECT_NEAR(ComputePlatePeak(map, {0.005, 1, 4}).pressure, kBase + kSlope * 0.0065, 1e-6);
}

TEST(PlateReading, AMapMovedAlongTheCellsReadsTheSamePeak) {
  // The cells are laid from the map's own bounds, so where the map lies does not matter. (The
  // field is constant along z, so only the peak cell's x is unique.)
  const PlanarPressureMap map = LinearMap(0.011);
  RigidMotion2d shift;
  shift.translation = Eigen::Vector2d(0.0123, -0.0071);
  const PlatePeak here = ComputePlatePeak(map), there = ComputePlatePeak(map.Moved(shift));
  EXPECT_NEAR(there.pressure, here.pressure, 1e-9 * here.pressure);
  EXPECT_NEAR(there.point.x(), here.point.x() + shift.translation.x(), 1e-12);
}

TEST(PlateReading, AMapWithoutPressureReadsZero) {
  const TriMesh grid = testing::MakeFlatGrid(0.01, 2);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(grid.vertices.rows());
  const PlanarPressureMap map = PlanarPressureMap::FromSurface(
      grid, zero, BarycentricVertexAreas(grid), PlanarPressureMap::Facing::kUp);
  EXPECT_EQ(ComputePlatePeak(map).pressure, 0);
}

TEST(PlateReading, OnlyALoadWithinTenDegreesOfDownIsSeenAlongY) {
  EXPECT_TRUE(LoadSeenAlongY(Eigen::Vector3d(0, -300, 0)));
  EXPECT_TRUE(LoadSeenAlongY(Eigen::Vector3d(std::sin(0.17), -std::cos(0.17), 0)));   // 9.7°
  EXPECT_FALSE(LoadSeenAlongY(Eigen::Vector3d(std::sin(0.18), -std::cos(0.18), 0)));  // 10.3°
  EXPECT_FALSE(LoadSeenAlongY(Eigen::Vector3d(0, 300, 0)));
  EXPECT_FALSE(LoadSeenAlongY(Eigen::Vector3d::Zero()));
}

}  // namespace
}  // namespace ergo
