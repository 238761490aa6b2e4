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
  std::optional<CsvHeader> header;
  int column_sensor = 0, column_x = 0, column_z = 0, column_value = 0;
  std::optional<int> column_reference;
  std::map<std::string, size_t> index_of;
  std::vector<std::string> fields;
  while (NextCsvRow(reader, &fields)) {
    if (!header) {
      header.emplace(reader, fields,
                     std::vector<std::string>{"sensor", "x_mm", "z_mm", "value", "reference"},
                     kColumns);
      column_sensor = header->Require(reader, "sensor");
      column_x = header->Require(reader, "x_mm");
      column_z = header->Require(reader, "z_mm");
      column_value = header->Require(reader, "value");
      column_reference = header->Find("reference");
      readings.has_reference = column_reference.has_value();
      readings.ignored_columns = header->ignored();
      continue;
    }
    header->CheckRow(reader, fields);
    const std::string& name = fields[column_sensor];
    if (name.empty())
      reader.Fail("the sensor's name is empty", "name the sensor's location, e.g. heel_1");
    if (name.size() > kMaxNameLength)
      reader.Fail("the sensor's name is longer than 128 characters", "use a short name");
    const Eigen::Vector2d point_mm(ParseCsvNumber(reader, fields[column_x], "x_mm"),
                                   ParseCsvNumber(reader, fields[column_z], "z_mm"));
    const double value = ParseCsvNumber(reader, fields[column_value], "value");
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
      reader.Fail("sensor " + Quote(name) + " is at (" + fields[column_x] + ", " +
                      fields[column_z] + ") mm here but at (" +
                      std::to_string(1e3 * record.point.x()) + ", " +
                      std::to_string(1e3 * record.point.y()) + ") mm on line " +
                      std::to_string(record.first_line),
                  "give each location its own name, and the same coordinates on all its rows");
    }
    record.values.push_back(value);
    if (column_reference)
      record.reference.push_back(ParseCsvNumber(reader, fields[*column_reference], "reference"));
  }
  if (!header) {
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
