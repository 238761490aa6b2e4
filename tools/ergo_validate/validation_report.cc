#include "tools/ergo_validate/validation_report.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "ergo/mesh/atomic_file.h"

namespace ergo {
namespace {

constexpr double kRadiansPerDegree = M_PI / 180;

Json Millimetres(const Eigen::Vector2d& point) {
  Json pair = Json::array();
  pair.push_back(1e3 * point.x());
  pair.push_back(1e3 * point.y());
  return pair;
}

Json MapJson(const MapSummary& map) {
  Json out = Json::object();
  out["total_force_n"] = map.total_force;
  out["peak_kpa"] = 1e-3 * map.peak;
  out["peak_at_mm"] = Millimetres(map.peak_point);
  out["centre_of_pressure_mm"] = Millimetres(map.centre_of_pressure);
  out["footprint_area_cm2"] = 1e4 * map.footprint_area;
  return out;
}

std::string Fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

std::string Point(const Eigen::Vector2d& point) {
  return "(" + Fixed(1e3 * point.x(), 1) + ", " + Fixed(1e3 * point.y(), 1) + ")";
}

}  // namespace

Json ComparisonJson(const ValidationRecord& record) {
  const PressureMapComparison& c = record.comparison;
  Json out = Json::object();
  out["tool"] = "ergo_validate";
  out["scenario"] = record.scenario;
  out["description"] = record.description;
  Json simulated = Json::object();
  simulated["side"] = record.simulated_side;
  simulated["load_n"] = record.load;
  out["simulated"] = simulated;
  Json measurement = record.measurement;
  measurement["kind"] = record.measurement_kind;
  measurement["file"] = record.measurement_file;
  out["measurement"] = measurement;

  Json alignment = Json::object();
  alignment["mode"] = AlignmentModeName(record.alignment_options.mode);
  alignment["score"] = AlignmentScoreName(record.alignment_options.score);
  alignment["grid_pitch_mm"] = 1e3 * record.alignment_options.grid_pitch;
  // q_simulated = R(angle) q_measured + translation, in the measured map's own frame (a
  // plate's: its first cell's corner at the origin).
  alignment["angle_deg"] = record.alignment.motion.angle / kRadiansPerDegree;
  alignment["translation_mm"] = Millimetres(record.alignment.motion.translation);
  alignment["initial_score"] = record.alignment.initial_score;
  alignment["score"] = record.alignment.score;
  alignment["evaluations"] = record.alignment.evaluations;
  alignment["description"] = record.alignment_description;
  out["alignment"] = alignment;

  out["footprint_threshold_kpa"] = 1e-3 * c.footprint_threshold;
  out["simulated_map"] = MapJson(c.simulated);
  out["measured_map"] = MapJson(c.measured);
  out["total_force_ratio"] =
      c.simulated.total_force > 0 ? c.measured.total_force / c.simulated.total_force : 0.0;
  out["peak_ratio"] = c.simulated.peak > 0 ? c.measured.peak / c.simulated.peak : 0.0;
  out["peak_distance_mm"] = 1e3 * c.peak_distance;
  if (c.cell_pitch > 0) {
    // The simulation read on the plate's own cells: the peak to compare a plate's with.
    Json cells = Json::object();
    cells["pitch_mm"] = 1e3 * c.cell_pitch;
    cells["simulated_peak_kpa"] = 1e-3 * c.simulated_cell_peak;
    cells["simulated_peak_at_mm"] = Millimetres(c.simulated_cell_peak_point);
    cells["peak_ratio"] = c.simulated_cell_peak > 0 ? c.measured.peak / c.simulated_cell_peak : 0.0;
    cells["peak_distance_mm"] = 1e3 * (c.simulated_cell_peak_point - c.measured.peak_point).norm();
    out["on_the_plates_cells"] = cells;
  }
  out["centre_of_pressure_distance_mm"] =
      1e3 * (c.simulated.centre_of_pressure - c.measured.centre_of_pressure).norm();
  out["correlation_defined"] = c.correlation_defined;
  out["pearson"] = c.pearson;
  out["union_nodes"] = c.union_nodes;
  out["dice"] = c.dice;
  out["iou"] = c.iou;
  Json axis = Json::object();
  axis["origin_mm"] = Millimetres(c.axis_origin);
  Json direction = Json::array();
  direction.push_back(c.axis_direction.x());
  direction.push_back(c.axis_direction.y());
  axis["direction_xz"] = direction;
  axis["length_mm"] = 1e3 * c.axis_length;
  out["axis"] = axis;
  Json regions = Json::array();
  for (const RegionComparison& region : c.regions) {
    Json r = Json::object();
    r["name"] = region.name;
    r["begin"] = region.begin;
    r["end"] = region.end;
    r["simulated_share"] = region.simulated_share;
    r["measured_share"] = region.measured_share;
    r["simulated_force_n"] = region.simulated_force;
    r["measured_force_n"] = region.measured_force;
    regions.push_back(r);
  }
  out["regions"] = regions;
  return out;
}

std::string ComparisonMarkdown(const ValidationRecord& record) {
  const PressureMapComparison& c = record.comparison;
  std::ostringstream md;
  md << "# Measured against simulated contact pressure\n\n"
     << "Scene: **" << record.scenario << "** (" << record.description << "); simulated map: the "
     << record.simulated_side << "'s pressures at equilibrium, load " << Fixed(record.load, 1)
     << " N.\n\nMeasurement: " << record.measurement_kind << " `" << record.measurement_file
     << "`.\n\nAlignment (" << AlignmentModeName(record.alignment_options.mode) << ", by "
     << AlignmentScoreName(record.alignment_options.score) << "): " << record.alignment_description
     << ".\n\n"
     << "Footprints: where the pressure exceeds " << Fixed(1e-3 * c.footprint_threshold, 2)
     << " kPa; fields compared on a " << Fixed(1e3 * c.grid.pitch, 1) << " mm grid.\n\n"
     << "| | simulated | measured |\n|---|---:|---:|\n"
     << "| total force, N | " << Fixed(c.simulated.total_force, 1) << " | "
     << Fixed(c.measured.total_force, 1) << " |\n"
     << "| peak pressure, kPa | " << Fixed(1e-3 * c.simulated.peak, 1) << " | "
     << Fixed(1e-3 * c.measured.peak, 1) << " |\n"
     << "| peak at (x, z), mm | " << Point(c.simulated.peak_point) << " | "
     << Point(c.measured.peak_point) << " |\n";
  if (c.cell_pitch > 0) {
    md << "| peak on the plate's " << Fixed(1e3 * c.cell_pitch, 1) << " mm cells, kPa | "
       << Fixed(1e-3 * c.simulated_cell_peak, 1) << " | " << Fixed(1e-3 * c.measured.peak, 1)
       << " |\n";
  }
  md << "| centre of pressure (x, z), mm | " << Point(c.simulated.centre_of_pressure) << " | "
     << Point(c.measured.centre_of_pressure) << " |\n"
     << "| footprint, cm² | " << Fixed(1e4 * c.simulated.footprint_area, 1) << " | "
     << Fixed(1e4 * c.measured.footprint_area, 1) << " |\n";
  for (const RegionComparison& region : c.regions) {
    md << "| " << region.name << " share (" << Fixed(region.begin, 2) << "–" << Fixed(region.end, 2)
       << " of the length) | " << Fixed(region.simulated_share, 3) << " | "
       << Fixed(region.measured_share, 3) << " |\n";
  }
  md << "\nPearson correlation over the union of the footprints: "
     << (c.correlation_defined ? Fixed(c.pearson, 3) : std::string("undefined (a constant field)"))
     << "; footprint overlap Dice " << Fixed(c.dice, 3) << ", IoU " << Fixed(c.iou, 3) << "; peaks "
     << Fixed(1e3 * c.peak_distance, 1) << " mm apart.\n\n"
     << "Regions are fractions of the simulated footprint's length along its principal axis "
        "(direction ("
     << Fixed(c.axis_direction.x(), 3) << ", " << Fixed(c.axis_direction.y(), 3) << ") in (x, z), "
     << Fixed(1e3 * c.axis_length, 1) << " mm long).\n";
  if (record.sensors != nullptr) {
    const SensorPressureMap& s = *record.sensors;
    md << "\nSensors: " << s.sensors.size() << " locations; " << s.BriefReport()
       << ". Per location: `sensors.csv`.\n";
  }
  md << "\nPicture: `comparison.png` (both maps on one colour scale, and their difference).\n";
  return md.str();
}

Json ValidationPlotData(const ValidationRecord& record) {
  const PressureMapComparison& c = record.comparison;
  Json out = Json::object();
  out["title"] = record.scenario + ": " + record.measurement_kind + " " + record.measurement_file;
  out["lower_mm"] = Millimetres(c.grid.lower);
  out["pitch_mm"] = 1e3 * c.grid.pitch;
  out["rows"] = c.grid.simulated.rows();
  out["columns"] = c.grid.simulated.cols();
  for (const auto& [key, field] :
       {std::pair<const char*, const Eigen::MatrixXd*>{"simulated_kpa", &c.grid.simulated},
        std::pair<const char*, const Eigen::MatrixXd*>{"measured_kpa", &c.grid.measured}}) {
    Json values = Json::array();
    for (Eigen::Index r = 0; r < field->rows(); ++r)
      for (Eigen::Index k = 0; k < field->cols(); ++k)
        values.push_back(std::round(1e-3 * (*field)(r, k) * 1e4) / 1e4);  // 0.1 Pa is plenty
    out[key] = values;
  }
  out["footprint_threshold_kpa"] = 1e-3 * c.footprint_threshold;
  out["simulated_peak_mm"] = Millimetres(c.simulated.peak_point);
  out["measured_peak_mm"] = Millimetres(c.measured.peak_point);
  out["axis_origin_mm"] = Millimetres(c.axis_origin);
  Json direction = Json::array();
  direction.push_back(c.axis_direction.x());
  direction.push_back(c.axis_direction.y());
  out["axis_direction"] = direction;
  out["axis_length_mm"] = 1e3 * c.axis_length;
  Json regions = Json::array();
  for (const RegionComparison& region : c.regions) {
    Json r = Json::object();
    r["name"] = region.name;
    r["begin"] = region.begin;
    r["end"] = region.end;
    r["simulated_share"] = region.simulated_share;
    r["measured_share"] = region.measured_share;
    regions.push_back(r);
  }
  out["regions"] = regions;
  out["pearson"] = c.pearson;
  out["dice"] = c.dice;
  if (record.sensors != nullptr) {
    // The sensors where they were measured, moved with the measured map.
    Json points = Json::array();
    for (const SensorEstimate& sensor : record.sensors->sensors)
      points.push_back(Millimetres(record.alignment.motion.Apply(sensor.point)));
    out["sensors_mm"] = points;
  }
  return out;
}

void WriteValidationFiles(const std::string& dir, const ValidationRecord& record) {
  const std::filesystem::path out(dir);
  WriteJsonFile((out / "comparison.json").string(), ComparisonJson(record));
  const std::string markdown = ComparisonMarkdown(record);
  WriteFileAtomically((out / "comparison.md").string(),
                      [&](std::ostream& stream) { stream << markdown; });
  WriteJsonFile((out / "maps.json").string(), ValidationPlotData(record), 0);
  if (record.sensors == nullptr) return;
  WriteFileAtomically((out / "sensors.csv").string(), [&](std::ostream& csv) {
    csv << "sensor,x_mm,z_mm,line,samples,kept,trimmed_mean,trimmed_sd,reference_mean,"
           "reference_sd,pressure_kpa,pressure_sd_kpa\n";
    for (const SensorEstimate& s : record.sensors->sensors) {
      csv << s.name << ",";
      for (double value : {1e3 * s.point.x(), 1e3 * s.point.y()}) {
        WriteDouble(csv, value);
        csv << ",";
      }
      csv << s.first_line << "," << s.samples << "," << s.kept << ",";
      for (double value : {s.mean, s.standard_deviation}) {
        WriteDouble(csv, value);
        csv << ",";
      }
      if (s.has_reference) {
        WriteDouble(csv, s.reference_mean);
        csv << ",";
        WriteDouble(csv, s.reference_standard_deviation);
      } else {
        csv << ",";
      }
      csv << ",";
      WriteDouble(csv, 1e-3 * s.pressure);
      csv << ",";
      WriteDouble(csv, 1e-3 * s.standard_deviation_pa);
      csv << "\n";
    }
  });
}

}  // namespace ergo
