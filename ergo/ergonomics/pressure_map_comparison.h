// How a measured contact-pressure map compares with the simulated one (paper §6, Fig. 14, in
// numbers), both seen along the load on the support's plane with the measured map already
// aligned (pressure_map_alignment.h):
//   - total force, peak pressure and where it is, centre of pressure, footprint area of each;
//   - region shares: the force in each region over the total, the regions being fractions
//     along the simulated footprint's principal axis (0 at one end, 1 at the end the axis
//     points to; the shoe: rearfoot, midfoot, forefoot thirds from the heel);
//   - Pearson's correlation of the two fields over the union of the footprints, and the
//     footprints' overlap: Dice 2|A∩B|/(|A|+|B|) and IoU |A∩B|/|A∪B|.
// Footprints are where the pressure exceeds one threshold for both maps; fields are sampled
// on one grid of pitch h over both maps; forces, shares and peaks are summed over each map's
// own force-carrying samples. Pa, m, N.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/ergonomics/planar_pressure_map.h"

namespace ergo {

// A region [begin, end) of fractions along the footprint's axis (the last one includes 1).
struct PressureRegion {
  std::string name;
  double begin = 0, end = 1;
};

// "rearfoot:0.3333,midfoot:0.6667,forefoot:1": NAME:END pairs with increasing ends, the last
// 1, each region beginning where the one before ends. false with *error saying why otherwise.
bool ParsePressureRegions(const std::string& text, std::vector<PressureRegion>* regions,
                          std::string* error);

struct ComparisonOptions {
  std::vector<PressureRegion> regions;
  // The footprint's principal axis is oriented to point along this direction of the plane
  // (x, z) (for the shoe +z, heel to toes); ties go to the axis as computed.
  Eigen::Vector2d axis_toward = Eigen::Vector2d(0, 1);
  double footprint_threshold = 0;  // Pa, > 0
  double grid_pitch = 0.002;       // m
  // The measured map's cell pitch when it is a plate (FromGrid), m; 0 otherwise. Then the
  // simulated map is also read on the plate's own cells, where the alignment laid them.
  double measured_cell_pitch = 0;
};

struct MapSummary {
  double total_force = 0;                                        // Σ p a over the samples, N
  double peak = 0;                                               // largest sample pressure, Pa
  Eigen::Vector2d peak_point = Eigen::Vector2d::Zero();          // m
  Eigen::Vector2d centre_of_pressure = Eigen::Vector2d::Zero();  // m
  double footprint_area = 0;  // grid nodes above threshold · h², m²
};

struct RegionComparison {
  std::string name;
  double begin = 0, end = 1;
  double simulated_force = 0, measured_force = 0;  // N
  double simulated_share = 0, measured_share = 0;  // of each map's total
};

// Both fields on the common grid (for pictures): node (row r, column c) at
// lower + pitch (c, r).
struct ComparisonGrid {
  Eigen::Vector2d lower = Eigen::Vector2d::Zero();
  double pitch = 0;
  Eigen::MatrixXd simulated, measured;  // rows x columns, Pa
};

struct PressureMapComparison {
  MapSummary simulated, measured;
  std::vector<RegionComparison> regions;
  // The axis: a point q lies at fraction ((q − axis_origin)·axis_direction) / axis_length.
  Eigen::Vector2d axis_origin = Eigen::Vector2d::Zero(), axis_direction = Eigen::Vector2d(0, 1);
  double axis_length = 0;
  double footprint_threshold = 0;    // Pa
  bool correlation_defined = false;  // false when either field is constant over the union
  double pearson = 0;
  long union_nodes = 0;
  double dice = 0, iou = 0;
  double peak_distance = 0;  // between the two peaks, m
  // With a plate (measured_cell_pitch > 0): the simulated map as the plate's cells, lying where
  // they lay, would have read it — the peak to hold against the plate's, its cell's centre
  // (m), and the plate's pitch (m); all 0 otherwise. A sample peak is per vertex, a plate's
  // per cell, and the two differ by the averaging alone (plate_reading.h).
  double simulated_cell_peak = 0;
  Eigen::Vector2d simulated_cell_peak_point = Eigen::Vector2d::Zero();
  double cell_pitch = 0;
  ComparisonGrid grid;

  // "Pearson 0.95, Dice 0.91, IoU 0.84; force 381.6 / 380.2 N; peak 444 / 431 kPa 3.1 mm
  // apart (the simulation on the plate's cells 429 kPa); shares rearfoot 0.52/0.50, ...".
  std::string BriefReport() const;
};

// `measured` is already in the simulated map's frame. options.regions must satisfy
// ParsePressureRegions' rules (CHECKed).
PressureMapComparison ComparePressureMaps(const PlanarPressureMap& simulated,
                                          const PlanarPressureMap& measured,
                                          const ComparisonOptions& options);

}  // namespace ergo
