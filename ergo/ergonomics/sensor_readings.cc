#include "ergo/ergonomics/sensor_readings.h"

#include <cmath>
#include <map>
#include <optional>

#include "ergo/ergonomics/csv_row.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

constexpr const char* kColumns = "sensor,x_mm,z_mm,value[,reference]";
// A sensor's rows must repeat its coordinates; they are written by the same software, so
// they agree to the digits printed — 1 µm allows for rounding to three decimals of a mm.
constexpr double kSameCoordinateMm = 1e-3;
constexpr size_t kMaxSensors = 100000;
constexpr size_t kMaxNameLength = 128;

}  // namespace

SensorReadings ReadSensorReadingsCsv(const std::string& path) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  SensorReadings readings;
  readings.source = path;
  std::optional<int> column_sensor, column_x, column_z, column_value, column_reference;
  size_t column_count = 0;
  bool header_read = false;
  std::map<std::string, size_t> index_of;
  std::string_view line;
  while (reader.NextLine(&line)) {
    reader.RequireRecordLength(line);
    std::string_view content = line;
    while (!content.empty() && (content.front() == ' ' || content.front() == '\t'))
      content.remove_prefix(1);
    if (content.empty() || content.front() == '#' ||
        content.find_first_not_of(" \t\r,;") == std::string_view::npos)
      continue;
    const std::vector<std::string> fields = SplitCsvRow(content);
    if (!header_read) {
      header_read = true;
      column_count = fields.size();
      for (size_t k = 0; k < fields.size(); ++k) {
        const std::string name = ToLower(fields[k]);
        std::optional<int>* slot = nullptr;
        if (name == "sensor") slot = &column_sensor;
        if (name == "x_mm") slot = &column_x;
        if (name == "z_mm") slot = &column_z;
        if (name == "value") slot = &column_value;
        if (name == "reference") slot = &column_reference;
        if (slot == nullptr) {
          readings.ignored_columns.push_back(fields[k]);
          continue;
        }
        if (slot->has_value())
          reader.Fail("the column " + Quote(fields[k]) + " is named twice",
                      "name each column once");
        *slot = static_cast<int>(k);
      }
      for (const auto& [column, name] :
           {std::pair{&column_sensor, "sensor"}, std::pair{&column_x, "x_mm"},
            std::pair{&column_z, "z_mm"}, std::pair{&column_value, "value"}}) {
        if (!column->has_value()) {
          reader.Fail(std::string("the header has no column '") + name + "'",
                      std::string("the first row must name the columns ") + kColumns);
        }
      }
      readings.has_reference = column_reference.has_value();
      continue;
    }
    if (fields.size() != column_count) {
      reader.Fail("has " + std::to_string(fields.size()) + " fields, the header " +
                      std::to_string(column_count),
                  "give every row the header's columns (" + std::string(kColumns) + ")");
    }
    const std::string& name = fields[*column_sensor];
    if (name.empty())
      reader.Fail("the sensor's name is empty", "name the sensor's location, e.g. heel_1");
    if (name.size() > kMaxNameLength)
      reader.Fail("the sensor's name is longer than 128 characters", "use a short name");
    const Eigen::Vector2d point_mm(ParseCsvNumber(reader, fields[*column_x], "x_mm"),
                                   ParseCsvNumber(reader, fields[*column_z], "z_mm"));
    const double value = ParseCsvNumber(reader, fields[*column_value], "value");
    auto [found, inserted] = index_of.emplace(name, readings.sensors.size());
    if (inserted) {
      if (readings.sensors.size() >= kMaxSensors)
        reader.Fail("more than 100000 sensors",
                    "give one row per sample of at most 100000 locations");
      SensorRecord record;
      record.name = name;
      record.point = 1e-3 * point_mm;
      record.first_line = reader.line_number();
      readings.sensors.push_back(record);
    }
    SensorRecord& record = readings.sensors[found->second];
    if ((1e3 * record.point - point_mm).cwiseAbs().maxCoeff() > kSameCoordinateMm) {
      reader.Fail("sensor " + Quote(name) + " is at (" + fields[*column_x] + ", " +
                      fields[*column_z] + ") mm here but at (" +
                      std::to_string(1e3 * record.point.x()) + ", " +
                      std::to_string(1e3 * record.point.y()) + ") mm on line " +
                      std::to_string(record.first_line),
                  "give each location its own name, and the same coordinates on all its rows");
    }
    record.values.push_back(value);
    if (column_reference)
      record.reference.push_back(ParseCsvNumber(reader, fields[*column_reference], "reference"));
  }
  if (!header_read) {
    throw InputError(path, "", "the file holds no header and no readings",
                     std::string("write a header row ") + kColumns + ", then one row per sample");
  }
  if (readings.sensors.empty()) {
    throw InputError(path, "", "the file holds a header but no readings",
                     "write one row per sample after the header");
  }
  return readings;
}

void WriteSensorReadingsCsv(const std::string& path, const SensorReadings& readings,
                            const std::vector<std::string>& comment) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    for (const std::string& line : comment) out << "# " << line << "\n";
    out << "sensor,x_mm,z_mm,value" << (readings.has_reference ? ",reference" : "") << "\n";
    for (const SensorRecord& sensor : readings.sensors) {
      for (size_t k = 0; k < sensor.values.size(); ++k) {
        out << sensor.name << ",";
        WriteDouble(out, 1e3 * sensor.point.x());
        out << ",";
        WriteDouble(out, 1e3 * sensor.point.y());
        out << ",";
        WriteDouble(out, sensor.values[k]);
        if (readings.has_reference) {
          out << ",";
          WriteDouble(out, sensor.reference[k]);
        }
        out << "\n";
      }
    }
  });
}

}  // namespace ergo
