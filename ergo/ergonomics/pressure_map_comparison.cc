#include "ergo/ergonomics/pressure_map_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>

#include "ergo/ergonomics/plate_reading.h"
#include "ergo/ergonomics/pressure_map_alignment.h"
#include "ergo/mesh/split_list.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

MapSummary Summarise(const PlanarPressureMap& map) {
  MapSummary summary;
  summary.total_force = map.TotalForce();
  const Eigen::VectorXd& pressure = map.sample_pressure();
  if (pressure.size() > 0) {
    Eigen::Index peak = 0;
    summary.peak = pressure.maxCoeff(&peak);
    summary.peak_point = map.sample_points().row(peak).transpose();
  }
  summary.centre_of_pressure = PressureCentroid(map);
  return summary;
}

// Index of the region holding fraction f (clamped to [0, 1]).
size_t RegionOf(const std::vector<PressureRegion>& regions, double f) {
  f = std::clamp(f, 0.0, 1.0);
  for (size_t k = 0; k + 1 < regions.size(); ++k)
    if (f < regions[k].end) return k;
  return regions.size() - 1;
}

}  // namespace

bool ParsePressureRegions(const std::string& text, std::vector<PressureRegion>* regions,
                          std::string* error) {
  const std::string usage =
      "write NAME:END pairs with increasing ends up to 1, e.g. "
      "rearfoot:0.3333,midfoot:0.6667,forefoot:1";
  std::vector<PressureRegion> parsed;
  double begin = 0;
  for (const std::string& item : SplitList(text, ',')) {
    const size_t colon = item.rfind(':');
    double end = 0;
    if (colon == std::string::npos || colon == 0 || !ParseDouble(item.substr(colon + 1), &end) ||
        !std::isfinite(end)) {
      *error = "'" + item + "' is not NAME:END: " + usage;
      return false;
    }
    if (!(end > begin) || end > 1) {
      *error = "'" + item + "' does not end after the region before it (at " +
               std::to_string(begin) + ") and at most at 1: " + usage;
      return false;
    }
    parsed.push_back(PressureRegion{item.substr(0, colon), begin, end});
    begin = end;
  }
  if (parsed.empty() || parsed.back().end != 1) {
    *error = "the regions must end at 1 (the far end of the footprint): " + usage;
    return false;
  }
  *regions = parsed;
  return true;
}

std::string PressureMapComparison::BriefReport() const {
  std::ostringstream out;
  out.precision(3);
  out << "Pearson ";
  if (correlation_defined) {
    out << pearson;
  } else {
    out << "undefined";
  }
  out << ", Dice " << dice << ", IoU " << iou << "; force " << simulated.total_force << " / "
      << measured.total_force << " N; peak " << simulated.peak * 1e-3 << " / "
      << measured.peak * 1e-3 << " kPa, " << peak_distance * 1e3 << " mm apart";
  if (cell_pitch > 0) {
    out << " (the simulation on the plate's " << cell_pitch * 1e3 << " mm cells "
        << simulated_cell_peak * 1e-3 << " kPa)";
  }
  out << "; shares";
  for (const RegionComparison& region : regions)
    out << " " << region.name << " " << region.simulated_share << "/" << region.measured_share;
  out << " (simulated/measured)";
  return out.str();
}

PressureMapComparison ComparePressureMaps(const PlanarPressureMap& simulated,
                                          const PlanarPressureMap& measured,
                                          const ComparisonOptions& options) {
  CHECK_GT(options.footprint_threshold, 0);
  CHECK_GT(options.grid_pitch, 0);
  CHECK(!options.regions.empty() && options.regions.back().end == 1);
  PressureMapComparison result;
  result.footprint_threshold = options.footprint_threshold;
  result.simulated = Summarise(simulated);
  result.measured = Summarise(measured);
  result.peak_distance = (result.simulated.peak_point - result.measured.peak_point).norm();
  if (options.measured_cell_pitch > 0 && measured.sample_pressure().size() > 0) {
    const Eigen::VectorXd reading =
        ReadOnCells(simulated, measured.sample_points(), options.measured_cell_pitch,
                    measured.placement().angle, /*subsamples=*/4);
    Eigen::Index cell = 0;
    result.simulated_cell_peak = reading.maxCoeff(&cell);
    result.simulated_cell_peak_point = measured.sample_points().row(cell).transpose();
    result.cell_pitch = options.measured_cell_pitch;
  }

  // Both fields on one grid over both maps.
  Eigen::Vector2d lower_s, upper_s, lower_m, upper_m;
  simulated.Bounds(&lower_s, &upper_s);
  measured.Bounds(&lower_m, &upper_m);
  const double h = options.grid_pitch;
  ComparisonGrid& grid = result.grid;
  grid.pitch = h;
  grid.lower = lower_s.cwiseMin(lower_m);
  const Eigen::Vector2d upper = upper_s.cwiseMax(upper_m);
  const auto columns = static_cast<Eigen::Index>(std::ceil((upper.x() - grid.lower.x()) / h)) + 1;
  const auto rows = static_cast<Eigen::Index>(std::ceil((upper.y() - grid.lower.y()) / h)) + 1;
  // Callers bound the grid (ergo_validate refuses more than 5 million nodes before any work).
  CHECK_LE(static_cast<double>(rows) * static_cast<double>(columns), 1e8)
      << "comparison grid too large";
  grid.simulated.resize(rows, columns);
  grid.measured.resize(rows, columns);
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < columns; ++c) {
      const Eigen::Vector2d q =
          grid.lower + h * Eigen::Vector2d(static_cast<double>(c), static_cast<double>(r));
      grid.simulated(r, c) = simulated.PressureAt(q);
      grid.measured(r, c) = measured.PressureAt(q);
    }
  }

  // Footprints, their overlap, Pearson over the union, and the simulated footprint's axis.
  const double threshold = options.footprint_threshold;
  long both = 0, only_simulated = 0, only_measured = 0;
  double sum_s = 0, sum_m = 0, sum_ss = 0, sum_mm = 0, sum_sm = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> simulated_footprint;
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < columns; ++c) {
      const double s = grid.simulated(r, c), m = grid.measured(r, c);
      const bool in_s = s > threshold, in_m = m > threshold;
      if (in_s && in_m) ++both;
      if (in_s && !in_m) ++only_simulated;
      if (!in_s && in_m) ++only_measured;
      if (in_s) {
        const Eigen::Vector2d q =
            grid.lower + h * Eigen::Vector2d(static_cast<double>(c), static_cast<double>(r));
        simulated_footprint.push_back(q);
        centroid += q;
      }
      if (in_s || in_m) {
        sum_s += s;
        sum_m += m;
        sum_ss += s * s;
        sum_mm += m * m;
        sum_sm += s * m;
      }
    }
  }
  const long simulated_nodes = both + only_simulated, measured_nodes = both + only_measured;
  result.simulated.footprint_area = static_cast<double>(simulated_nodes) * h * h;
  result.measured.footprint_area = static_cast<double>(measured_nodes) * h * h;
  result.union_nodes = both + only_simulated + only_measured;
  if (simulated_nodes + measured_nodes > 0)
    result.dice =
        2.0 * static_cast<double>(both) / static_cast<double>(simulated_nodes + measured_nodes);
  if (result.union_nodes > 0)
    result.iou = static_cast<double>(both) / static_cast<double>(result.union_nodes);
  if (result.union_nodes > 1) {
    const double n = static_cast<double>(result.union_nodes);
    const double covariance = sum_sm - sum_s * sum_m / n;
    const double variance_s = sum_ss - sum_s * sum_s / n, variance_m = sum_mm - sum_m * sum_m / n;
    if (variance_s > 0 && variance_m > 0) {
      result.correlation_defined = true;
      result.pearson = covariance / std::sqrt(variance_s * variance_m);
    }
  }

  // The simulated footprint's principal axis (its nodes weighted alike: the outline's shape,
  // not where the load sits) and its extent along it.
  if (!simulated_footprint.empty()) {
    centroid /= static_cast<double>(simulated_footprint.size());
    Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& q : simulated_footprint)
      covariance += (q - centroid) * (q - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    Eigen::Vector2d direction = eigen.eigenvectors().col(1);  // the largest eigenvalue's
    if (direction.dot(options.axis_toward) < 0) direction = -direction;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Eigen::Vector2d& q : simulated_footprint) {
      low = std::min(low, (q - centroid).dot(direction));
      high = std::max(high, (q - centroid).dot(direction));
    }
    result.axis_direction = direction;
    result.axis_origin = centroid + low * direction;
    result.axis_length = std::max(high - low, h);
  }

  // Region shares from each map's own samples.
  for (const PressureRegion& region : options.regions)
    result.regions.push_back(RegionComparison{region.name, region.begin, region.end});
  auto add_forces = [&](const PlanarPressureMap& map, bool is_simulated) {
    for (Eigen::Index i = 0; i < map.sample_pressure().size(); ++i) {
      const double force = std::max(map.sample_pressure()[i], 0.0) * map.sample_area()[i];
      if (force == 0) continue;
      const Eigen::Vector2d q = map.sample_points().row(i).transpose();
      const double f = (q - result.axis_origin).dot(result.axis_direction) / result.axis_length;
      RegionComparison& region = result.regions[RegionOf(options.regions, f)];
      (is_simulated ? region.simulated_force : region.measured_force) += force;
    }
  };
  add_forces(simulated, true);
  add_forces(measured, false);
  double total_s = 0, total_m = 0;
  for (const RegionComparison& region : result.regions) {
    total_s += region.simulated_force;
    total_m += region.measured_force;
  }
  for (RegionComparison& region : result.regions) {
    region.simulated_share = total_s > 0 ? region.simulated_force / total_s : 0;
    region.measured_share = total_m > 0 ? region.measured_force / total_m : 0;
  }
  return result;
}

}  // namespace ergo
