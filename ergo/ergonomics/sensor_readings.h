// Point-sensor readings of a contact-pressure measurement (paper §6: a Tekscan A101 moved over
// 78 marked locations of the shoe sole, 600 samples at 10 Hz at each, a reference sensor fixed
// under the sole recorded at the same time). The file is a CSV with one row per sample:
//
//   # any comment line starts with '#'
//   sensor,x_mm,z_mm,value,reference
//   heel_1,12.5,-110.0,1.532,0.481
//
// `sensor` names the location; x_mm, z_mm place it on the support seen from above, in the
// support's own frame (ergo's convention: y up; the generated shoe sole: the foot along +z,
// heel towards −z), in millimetres; `value` is the reading and `reference` the reference
// sensor's reading taken with it (optional column). Readings may be in any unit proportional
// to pressure with zero offset (kPa, N, volts through a linear circuit): the map is scaled to
// the load afterwards (sensor_pressure_map.h). Rows of one sensor may be interleaved with
// others' and must repeat its coordinates. Other columns (a time stamp) are ignored.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace ergo {

struct SensorRecord {
  std::string name;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // (x, z), m
  int first_line = 0;                               // 1-based line of its first sample
  std::vector<double> values;
  std::vector<double> reference;  // empty when the file has no reference column
};

struct SensorReadings {
  std::string source;  // the file
  bool has_reference = false;
  std::vector<SensorRecord> sensors;         // in order of first appearance
  std::vector<std::string> ignored_columns;  // header names that are not read
};

// Throws InputError naming the file, the line and the column for anything unusable.
SensorReadings ReadSensorReadingsCsv(const std::string& path);

// Writes `readings` in the format above (atomically), `comment` lines first (each prefixed
// with "# "), the samples of each sensor together.
void WriteSensorReadingsCsv(const std::string& path, const SensorReadings& readings,
                            const std::vector<std::string>& comment);

}  // namespace ergo
