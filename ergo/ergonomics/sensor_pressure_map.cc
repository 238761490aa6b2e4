#include "ergo/ergonomics/sensor_pressure_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

std::string Millimetres(const Eigen::Vector2d& point) {
  std::ostringstream out;
  out << "(" << 1e3 * point.x() << ", " << 1e3 * point.y() << ") mm";
  return out.str();
}

}  // namespace

std::string SensorPressureMap::BriefReport() const {
  std::ostringstream out;
  out << sensors.size() << " sensor locations, C = " << scale << ", total force " << total_force
      << " N";
  if (lowest_interpolated < 0)
    out << "; interpolant down to " << lowest_interpolated * 1e-3 << " kPa set to 0 over "
        << clamped_area * 1e4 << " cm²";
  if (reference_variation > 0)
    out << "; reference means vary by " << 100 * reference_variation << " %";
  return out.str();
}

SensorPressureMap EstimateSensorPressureMap(const SensorReadings& readings, const SupportTop& top,
                                            const SensorMapOptions& options) {
  CHECK_GT(options.load, 0);
  const std::string& path = readings.source;
  SensorPressureMap map;
  std::vector<SurfacePoint> handles;
  Eigen::VectorXd normalized(static_cast<Eigen::Index>(readings.sensors.size()));
  double reference_sum = 0, reference_squares = 0;
  for (const SensorRecord& record : readings.sensors) {
    const std::string where = "line " + std::to_string(record.first_line);
    SensorEstimate estimate;
    estimate.name = record.name;
    estimate.point = record.point;
    estimate.first_line = record.first_line;
    estimate.samples = static_cast<long>(record.values.size());
    PlanarHit hit;
    if (!top.Locate(record.point, &hit)) {
      throw InputError(path, where,
                       "sensor '" + record.name + "' at " + Millimetres(record.point) +
                           " lies outside the support's top (seen from above it spans x " +
                           std::to_string(1e3 * top.lower().x()) + " to " +
                           std::to_string(1e3 * top.upper().x()) + " mm, z " +
                           std::to_string(1e3 * top.lower().y()) + " to " +
                           std::to_string(1e3 * top.upper().y()) + " mm)",
                       "give x_mm, z_mm in the support's own frame (y up; the shoe: foot along "
                       "+z), in millimetres");
    }
    handles.push_back(SurfacePoint{hit.triangle, hit.barycentric});
    TrimmedStatistics values;
    if (!ComputeTrimmedStatistics(record.values, options.trim, &values)) {
      throw InputError(path, where,
                       "sensor '" + record.name + "' has " + std::to_string(estimate.samples) +
                           " samples and the trim (" + options.trim.Describe() + ") leaves none",
                       "give more samples, or a smaller --trim (a fraction such as 50/600 "
                       "suits any count)");
    }
    estimate.mean = values.mean;
    estimate.standard_deviation = values.standard_deviation;
    estimate.kept = values.kept;
    if (readings.has_reference) {
      TrimmedStatistics reference;
      CHECK(ComputeTrimmedStatistics(record.reference, options.trim, &reference));
      if (!(reference.mean > 0)) {
        std::ostringstream what;
        what << "the reference sensor's trimmed mean while sensor '" << record.name
             << "' was read is " << reference.mean
             << ": it must be positive to normalise by (α_i r_i = C)";
        throw InputError(path, where, what.str(),
                         "fix the reference column, or drop it to compare without posture "
                         "normalisation");
      }
      estimate.has_reference = true;
      estimate.reference_mean = reference.mean;
      estimate.reference_standard_deviation = reference.standard_deviation;
      reference_sum += reference.mean;
      reference_squares += reference.mean * reference.mean;
    }
    normalized[static_cast<Eigen::Index>(map.sensors.size())] =
        estimate.mean / estimate.reference_mean;
    map.sensors.push_back(estimate);
  }
  if (readings.has_reference && map.sensors.size() > 1) {
    const double n = static_cast<double>(map.sensors.size());
    const double mean = reference_sum / n;
    const double variance = std::max(0.0, (reference_squares - n * mean * mean) / (n - 1));
    map.reference_variation = std::sqrt(variance) / mean;
  }

  const BiharmonicWeights weights =
      ComputeBiharmonicWeights(top.surface(), handles, options.interpolation);
  if (!weights.ok) {
    throw InputError(path, "", "the sensor locations cannot determine a map: " + weights.message,
                     "measure at least three locations spread over the support, each at its own "
                     "point");
  }
  Eigen::VectorXd unit_map = weights.Interpolate(normalized);  // the map for C = 1
  map.lowest_interpolated = unit_map.minCoeff();
  const Eigen::VectorXd& areas = top.vertex_areas();
  for (Eigen::Index v = 0; v < unit_map.size(); ++v) {
    if (unit_map[v] < 0) {
      map.clamped_area += areas[v];
      unit_map[v] = 0;
    }
  }
  // The clamp commutes with a positive scale, so the force is linear in C.
  const double unit_force = unit_map.dot(areas);
  if (!(unit_force > 0)) {
    throw InputError(path, "", "the sensors read no pressure anywhere (every trimmed mean <= 0)",
                     "check the value column: readings must grow with pressure from zero");
  }
  map.scale = options.load / unit_force;
  map.top_pressure = map.scale * unit_map;
  map.lowest_interpolated *= map.scale;
  map.total_force = map.top_pressure.dot(areas);
  for (SensorEstimate& estimate : map.sensors) {
    const double alpha = map.scale / estimate.reference_mean;
    estimate.pressure = alpha * estimate.mean;
    estimate.standard_deviation_pa = alpha * estimate.standard_deviation;
  }
  return map;
}

}  // namespace ergo
