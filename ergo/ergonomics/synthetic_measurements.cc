#include "ergo/ergonomics/synthetic_measurements.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <glog/logging.h>

#include "ergo/ergonomics/plate_reading.h"
#include "ergo/ergonomics/pressure_map_alignment.h"

namespace ergo {
namespace {

// β_i is kept within [0.5, 1.5]: a normal factor could otherwise (at 5σ for the default
// spread) turn a reading negative, which no posture does.
constexpr double kLowestPosture = 0.5, kHighestPosture = 1.5;

}  // namespace

SyntheticPlate MakeSyntheticPlate(const PlanarPressureMap& truth,
                                  const SyntheticPlateOptions& options) {
  CHECK_GT(options.pitch, 0);
  CHECK_GE(options.subsamples, 1);
  CHECK_GE(options.margin_cells, 0);
  const RigidMotion2d placed =
      RigidMotion2d::About(PressureCentroid(truth), options.rotation, options.shift);
  const PlanarPressureMap moved = truth.Moved(placed);
  SyntheticPlate plate;
  plate.grid = ReadOnCoveringPlate(moved, options.pitch, Eigen::Vector2d::Zero(),
                                   options.margin_cells, options.subsamples);
  const Eigen::Vector2d corner = plate.grid.origin;
  plate.grid.origin = Eigen::Vector2d::Zero();  // the plate's own frame
  if (options.noise > 0) {
    std::mt19937 random(options.seed);
    std::normal_distribution<double> normal(0.0, options.noise * plate.grid.pressure.maxCoeff());
    for (Eigen::Index i = 0; i < plate.grid.pressure.size(); ++i) {
      double& cell = plate.grid.pressure.data()[i];
      if (cell > 0) cell = std::max(0.0, cell + normal(random));
    }
  }
  RigidMotion2d to_corner;
  to_corner.translation = corner;
  plate.plate_to_map = placed.Inverse().After(to_corner);
  return plate;
}

SensorReadings MakeSyntheticSensorReadings(const PlanarPressureMap& truth, const SupportTop& top,
                                           const SyntheticSensorOptions& options) {
  CHECK_GT(options.pitch, 0);
  CHECK_GE(options.samples, 1);
  SensorReadings readings;
  readings.has_reference = true;
  Eigen::Index peak = 0;
  truth.sample_pressure().maxCoeff(&peak);
  const double reference_pressure = truth.PressureAt(truth.sample_points().row(peak).transpose());
  CHECK_GT(reference_pressure, 0) << "the map carries no pressure";

  std::mt19937 random(options.seed);
  std::normal_distribution<double> posture(1.0, options.posture);
  std::normal_distribution<double> noise(0.0, options.noise);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto reading = [&](double clean) {
    const double u = uniform(random);
    if (u < 0.5 * options.outliers) return 0.0;
    const double value = clean * (1 + noise(random));
    return u < options.outliers ? 3 * value : value;
  };
  const Eigen::Vector2d lower = top.lower(), upper = top.upper();
  const int nx = static_cast<int>(std::floor((upper.x() - lower.x()) / options.pitch));
  const int nz = static_cast<int>(std::floor((upper.y() - lower.y()) / options.pitch));
  // The lattice centred on the top's bounding box.
  const Eigen::Vector2d start =
      0.5 * (lower + upper) - 0.5 * options.pitch * Eigen::Vector2d(nx - 1, nz - 1);
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Eigen::Vector2d q = start + options.pitch * Eigen::Vector2d(i, j);
      PlanarHit hit;
      if (!top.Locate(q, &hit)) continue;
      SensorRecord record;
      char name[32];
      std::snprintf(name, sizeof(name), "s%03zu", readings.sensors.size() + 1);
      record.name = name;
      record.point = q;
      const double lean = std::clamp(posture(random), kLowestPosture, kHighestPosture);
      const double pressure = truth.PressureAt(q);
      for (int k = 0; k < options.samples; ++k) {
        record.values.push_back(reading(options.gain * lean * pressure));
        record.reference.push_back(reading(options.reference_gain * lean * reference_pressure));
      }
      readings.sensors.push_back(std::move(record));
    }
  }
  return readings;
}

}  // namespace ergo
