// What ergo_validate writes: comparison.json (every number, units in the keys), comparison.md
// (the same for people), maps.json (both maps on one grid, for tools/plot_validation.py) and,
// for point sensors, sensors.csv (each location's trimmed statistics, reference and
// pressure). Every file is written atomically into the run's temporary output directory.
#pragma once

#include <string>

#include "ergo/ergonomics/pressure_map_alignment.h"
#include "ergo/ergonomics/pressure_map_comparison.h"
#include "ergo/ergonomics/sensor_pressure_map.h"
#include "ergo/mesh/json.h"

namespace ergo {

struct ValidationRecord {
  std::string scenario, description;  // the simulated scene
  std::string simulated_side;         // "skin" or "support"
  double load = 0;                    // N
  std::string measurement_kind;       // "plate" or "sensors"
  std::string measurement_file;
  Json measurement = Json::object();  // the kind's details (pitch, unit, trim, C, ...)
  AlignmentOptions alignment_options;
  PressureMapAlignment alignment;
  std::string alignment_description;
  PressureMapComparison comparison;
  const SensorPressureMap* sensors = nullptr;  // for sensors.csv
};

Json ComparisonJson(const ValidationRecord& record);
std::string ComparisonMarkdown(const ValidationRecord& record);
// Both fields on the comparison grid in kPa and mm, the footprint threshold, the regions'
// boundaries along the axis, the peaks and, for sensors, their locations.
Json ValidationPlotData(const ValidationRecord& record);

// DIR/comparison.json, comparison.md, maps.json and (sensors) sensors.csv.
void WriteValidationFiles(const std::string& dir, const ValidationRecord& record);

}  // namespace ergo
