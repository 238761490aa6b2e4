// The comparison's numbers on maps whose answers are known: a map against itself, three bands
// of known force along the footprint's axis, a footprint against itself shifted by half its
// length; the regions' parser; and the planar map's field, samples and motion.
#include "ergo/ergonomics/pressure_map_comparison.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ergo/ergonomics/synthetic_measurements.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/flat_grid.h"

namespace ergo {
namespace {

std::vector<PressureRegion> Thirds() {
  std::vector<PressureRegion> regions;
  std::string error;
  EXPECT_TRUE(ParsePressureRegions("rearfoot:0.3333,midfoot:0.6667,forefoot:1", &regions, &error))
      << error;
  return regions;
}

// 10 columns (x) by 30 rows (z) of 5 mm cells: rows 0–9 at 200 kPa, 10–19 at 50 kPa, 20–29
// at 100 kPa.
PressureGrid Bands() {
  PressureGrid grid;
  grid.pitch = 0.005;
  grid.pressure.resize(30, 10);
  for (Eigen::Index r = 0; r < 30; ++r)
    grid.pressure.row(r).setConstant(r < 10 ? 200e3 : r < 20 ? 50e3 : 100e3);
  return grid;
}

TEST(ErgonomicsComparison, AMapAgainstItselfAgreesInEveryNumber) {
  const PlanarPressureMap map = PlanarPressureMap::FromGrid(Bands());
  ComparisonOptions options;
  options.regions = Thirds();
  options.footprint_threshold = 4e3;
  const PressureMapComparison c = ComparePressureMaps(map, map, options);
  EXPECT_TRUE(c.correlation_defined);
  EXPECT_NEAR(c.pearson, 1, 1e-12);
  EXPECT_EQ(c.dice, 1);
  EXPECT_EQ(c.iou, 1);
  EXPECT_EQ(c.peak_distance, 0);
  EXPECT_DOUBLE_EQ(c.simulated.total_force, c.measured.total_force);
  for (const RegionComparison& region : c.regions)
    EXPECT_DOUBLE_EQ(region.simulated_share, region.measured_share);
}

// The footprint's axis runs along z (30 rows against 10 columns), oriented to +z; its thirds
// split the bands at their boundaries, so the shares are 200 : 50 : 100.
TEST(ErgonomicsComparison, RegionSharesFollowTheFootprintsAxis) {
  const PlanarPressureMap map = PlanarPressureMap::FromGrid(Bands());
  ComparisonOptions options;
  options.regions = Thirds();
  options.footprint_threshold = 4e3;
  const PressureMapComparison c = ComparePressureMaps(map, map, options);
  EXPECT_NEAR(std::abs(c.axis_direction.y()), 1, 1e-9);
  EXPECT_GT(c.axis_direction.y(), 0);
  ASSERT_EQ(c.regions.size(), 3u);
  EXPECT_NEAR(c.regions[0].simulated_share, 200.0 / 350, 1e-12);
  EXPECT_NEAR(c.regions[1].simulated_share, 50.0 / 350, 1e-12);
  EXPECT_NEAR(c.regions[2].simulated_share, 100.0 / 350, 1e-12);
  EXPECT_NEAR(c.simulated.total_force, 0.005 * 0.005 * 10 * (10 * 200e3 + 10 * 50e3 + 10 * 100e3),
              1e-9);
  // Pointed the other way, the first region is the 100 kPa band.
  options.axis_toward = Eigen::Vector2d(0, -1);
  const PressureMapComparison reversed = ComparePressureMaps(map, map, options);
  EXPECT_NEAR(reversed.regions[0].simulated_share, 100.0 / 350, 1e-12);
}

// A uniform footprint against itself shifted by half its length along its axis: they overlap
// on half of each, Dice ≈ 1/2 and IoU ≈ 1/3 (the bilinear edges blur this by a cell).
TEST(ErgonomicsComparison, HalfShiftedFootprintsOverlapByHalf) {
  PressureGrid grid;
  grid.pitch = 0.005;
  grid.pressure = Eigen::MatrixXd::Constant(40, 10, 100e3);
  const PlanarPressureMap map = PlanarPressureMap::FromGrid(grid);
  RigidMotion2d half;
  half.translation = Eigen::Vector2d(0, 0.1);
  ComparisonOptions options;
  options.regions = Thirds();
  options.footprint_threshold = 50e3;  // the footprints' edges at the outer cells' borders
  const PressureMapComparison c = ComparePressureMaps(map, map.Moved(half), options);
  EXPECT_NEAR(c.dice, 0.5, 0.02);
  EXPECT_NEAR(c.iou, 1.0 / 3, 0.02);
  EXPECT_LT(c.pearson, 0);  // where one is loaded the other mostly is not
}

// A plate's peak is a cell's mean; the simulation read on that plate's own cells, where the
// alignment laid them, reads what the plate read. A noise-free synthetic plate of a tent
// (turned 8°, shifted) laid back by its true motion: the cell readings agree to rounding,
// while the tent's vertex peak stands above both (a cell averages the apex's slopes).
TEST(ErgonomicsComparison, TheSimulationOnThePlatesOwnCellsReadsWhatThePlateRead) {
  const TriMesh grid = testing::MakeFlatGrid(0.03, 12);
  Eigen::VectorXd pressure(grid.vertices.rows());
  for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v) {
    const double r = std::hypot(grid.vertices(v, 0) - 0.005, grid.vertices(v, 2) + 0.005);
    pressure[v] = std::max(0.0, 300e3 * (1 - r / 0.02));
  }
  const PlanarPressureMap simulated = PlanarPressureMap::FromSurface(
      grid, pressure, BarycentricVertexAreas(grid), PlanarPressureMap::Facing::kUp);
  SyntheticPlateOptions plate_options;
  plate_options.rotation = 8 * M_PI / 180;
  plate_options.shift = Eigen::Vector2d(0.012, -0.007);
  plate_options.noise = 0;
  const SyntheticPlate plate = MakeSyntheticPlate(simulated, plate_options);
  const PlanarPressureMap measured =
      PlanarPressureMap::FromGrid(plate.grid).Moved(plate.plate_to_map);
  ComparisonOptions options;
  options.regions = Thirds();
  options.footprint_threshold = 1e3;
  options.measured_cell_pitch = plate_options.pitch;
  const PressureMapComparison c = ComparePressureMaps(simulated, measured, options);
  EXPECT_EQ(c.cell_pitch, 0.005);
  EXPECT_NEAR(c.simulated_cell_peak, c.measured.peak, 1e-9 * c.measured.peak);
  EXPECT_NEAR((c.simulated_cell_peak_point - c.measured.peak_point).norm(), 0, 1e-12);
  // The apex sits on a vertex (300 kPa). A 5 mm cell centred on a cone of radius 20 mm averages
  // 1 − 0.383·5/20 = 0.904 of the apex (the mean distance from a square's centre is 0.383 of
  // its side), and the mesh's interpolant lies below the cone, so no cell reads above 271 kPa.
  EXPECT_NEAR(c.simulated.peak, 300e3, 1e-6);
  EXPECT_LT(c.measured.peak, 0.905 * 300e3);
  EXPECT_NE(c.BriefReport().find("the simulation on the plate's 5 mm cells"), std::string::npos);
  // Without a plate's pitch there is no cell reading.
  options.measured_cell_pitch = 0;
  EXPECT_EQ(ComparePressureMaps(simulated, measured, options).simulated_cell_peak, 0);
}

TEST(ErgonomicsComparison, RegionsParser) {
  std::vector<PressureRegion> regions;
  std::string error;
  ASSERT_TRUE(ParsePressureRegions("heel:0.3,rest:1", &regions, &error)) << error;
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[1].name, "rest");
  EXPECT_EQ(regions[1].begin, 0.3);
  for (const char* bad : {"", "heel", "heel:0.5", "a:0.5,b:0.4,c:1", "a:1.5", ":1", "a:x,b:1"}) {
    SCOPED_TRACE(bad);
    EXPECT_FALSE(ParsePressureRegions(bad, &regions, &error));
    EXPECT_NE(error.find("rearfoot:0.3333"), std::string::npos) << error;
  }
}

// The field of a surface map is piecewise linear (exact for a linear field), its samples are
// its vertices, and a motion moves both.
TEST(ErgonomicsPlanarMap, SurfaceFieldSamplesAndMotion) {
  const TriMesh grid = testing::MakeFlatGrid(0.05, 10);
  Eigen::VectorXd pressure(grid.vertices.rows());
  for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v)
    pressure[v] = 50e3 + 1e5 * grid.vertices(v, 0) + 3e5 * grid.vertices(v, 2);
  const PlanarPressureMap map = PlanarPressureMap::FromSurface(
      grid, pressure, BarycentricVertexAreas(grid), PlanarPressureMap::Facing::kUp);
  const Eigen::Vector2d q(0.0123, -0.0311);
  EXPECT_NEAR(map.PressureAt(q), 50e3 + 1e5 * q.x() + 3e5 * q.y(), 1e-8);
  EXPECT_EQ(map.PressureAt(Eigen::Vector2d(0.06, 0)), 0);
  // Seen facing down, the grid (normals +y) carries no field.
  const PlanarPressureMap below = PlanarPressureMap::FromSurface(
      grid, pressure, BarycentricVertexAreas(grid), PlanarPressureMap::Facing::kDown);
  EXPECT_EQ(below.PressureAt(q), 0);
  const RigidMotion2d motion =
      RigidMotion2d::About(Eigen::Vector2d(0.01, 0), 0.3, Eigen::Vector2d(0.02, -0.01));
  const PlanarPressureMap moved = map.Moved(motion);
  EXPECT_NEAR(moved.PressureAt(motion.Apply(q)), map.PressureAt(q), 1e-8);
  EXPECT_NEAR((moved.sample_points().row(7).transpose() -
               motion.Apply(map.sample_points().row(7).transpose()))
                  .norm(),
              0, 1e-15);
  EXPECT_DOUBLE_EQ(moved.TotalForce(), map.TotalForce());
  // The motion's algebra.
  const RigidMotion2d identity = motion.Inverse().After(motion);
  EXPECT_NEAR(identity.angle, 0, 1e-15);
  EXPECT_LT(identity.translation.norm(), 1e-15);
}

// Per-vertex forces on a skin-like surface (facing down) become pressures over the area each
// vertex covers seen from below, so the field carries exactly the forces: here a grid
// stretched 1.5 times along x, whose rest areas would understate the covered area.
TEST(ErgonomicsPlanarMap, VertexForcesBecomePressureOverTheCoveredArea) {
  TriMesh grid = testing::MakeFlatGrid(0.05, 10);
  for (Eigen::Index f = 0; f < grid.triangles.rows(); ++f)
    std::swap(grid.triangles(f, 1), grid.triangles(f, 2));
  grid.vertices.col(0) *= 1.5;
  Eigen::VectorXd force(grid.vertices.rows());
  for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v)
    force[v] = std::max(0.0, 2 - 40 * grid.vertices.row(v).norm());  // N, a central patch
  const PlanarPressureMap map =
      PlanarPressureMap::FromVertexForces(grid, force, PlanarPressureMap::Facing::kDown);
  EXPECT_NEAR(map.TotalForce(), force.sum(), 1e-12 * force.sum());
  EXPECT_EQ(map.unplaced_force(), 0);
  // The field's integral (midpoint rule on a fine grid; the field is piecewise linear, so
  // the rule's error is O(step²) of the curvature where it kinks: 0.5 % at 0.25 mm).
  double integral = 0;
  const double step = 0.00025;
  for (double x = -0.075 + step / 2; x < 0.075; x += step)
    for (double z = -0.05 + step / 2; z < 0.05; z += step)
      integral += map.PressureAt({x, z}) * step * step;
  EXPECT_NEAR(integral, force.sum(), 0.005 * force.sum());
  // An interior vertex covers 1.5 × (10 mm)² seen from below.
  const Eigen::Index centre = 5 * 11 + 5;
  EXPECT_NEAR(map.sample_pressure()[centre], force[centre] / (1.5 * 1e-4),
              1e-6 * force[centre] / 1.5e-4);
}

}  // namespace
}  // namespace ergo
