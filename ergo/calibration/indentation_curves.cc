#include "ergo/calibration/indentation_curves.h"

#include <cmath>
#include <map>
#include <optional>

#include "ergo/ergonomics/csv_row.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

constexpr const char* kColumns = "sample,x,y,z,indentation,force[,depth]";
// A sample's rows repeat its coordinates as the same software printed them: 1 µm allows for
// rounding to three decimals of a millimetre.
constexpr double kSameCoordinateM = 1e-6;
constexpr size_t kMaxSamples = 100000;
constexpr size_t kMaxNameLength = 128;

}  // namespace

IndentationCurves ReadIndentationCurvesCsv(const std::string& path, LengthUnit unit) {
  const double metres = MetresPerUnit(unit);
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  IndentationCurves curves;
  curves.source = path;
  std::optional<int> column_sample, column_x, column_y, column_z, column_indentation, column_force,
      column_depth;
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
      const std::map<std::string, std::optional<int>*> slots = {
          {"sample", &column_sample},
          {"x", &column_x},
          {"y", &column_y},
          {"z", &column_z},
          {"indentation", &column_indentation},
          {"force", &column_force},
          {"depth", &column_depth}};
      for (size_t k = 0; k < fields.size(); ++k) {
        const auto slot = slots.find(ToLower(fields[k]));
        if (slot == slots.end()) {
          curves.ignored_columns.push_back(fields[k]);
          continue;
        }
        if (slot->second->has_value())
          reader.Fail("the column " + Quote(fields[k]) + " is named twice",
                      "name each column once");
        *slot->second = static_cast<int>(k);
      }
      for (const auto& [column, name] :
           {std::pair{&column_sample, "sample"}, std::pair{&column_x, "x"},
            std::pair{&column_y, "y"}, std::pair{&column_z, "z"},
            std::pair{&column_indentation, "indentation"}, std::pair{&column_force, "force"}}) {
        if (!column->has_value()) {
          reader.Fail(std::string("the header has no column '") + name + "'",
                      std::string("the first row must name the columns ") + kColumns);
        }
      }
      curves.has_depth = column_depth.has_value();
      continue;
    }
    if (fields.size() != column_count) {
      reader.Fail("has " + std::to_string(fields.size()) + " fields, the header " +
                      std::to_string(column_count),
                  "give every row the header's columns (" + std::string(kColumns) + ")");
    }
    const std::string& name = fields[*column_sample];
    if (name.empty())
      reader.Fail("the sample's name is empty", "name the measured point, e.g. heel_1");
    if (name.size() > kMaxNameLength)
      reader.Fail("the sample's name is longer than 128 characters", "use a short name");
    const Eigen::Vector3d point =
        metres * Eigen::Vector3d(ParseCsvNumber(reader, fields[*column_x], "x"),
                                 ParseCsvNumber(reader, fields[*column_y], "y"),
                                 ParseCsvNumber(reader, fields[*column_z], "z"));
    const double indentation =
        metres * ParseCsvNumber(reader, fields[*column_indentation], "indentation");
    const double force = ParseCsvNumber(reader, fields[*column_force], "force");
    double depth = 0;
    if (column_depth) {
      depth = metres * ParseCsvNumber(reader, fields[*column_depth], "depth");
      if (depth <= 0)
        reader.Fail("depth " + Quote(fields[*column_depth]) + " is not positive",
                    "give the layer's measured depth, or leave the column out");
    }
    auto [found, inserted] = index_of.emplace(name, curves.curves.size());
    if (inserted) {
      if (curves.curves.size() >= kMaxSamples)
        reader.Fail("more than 100000 samples", "give the curves of at most 100000 points");
      IndentationCurve curve;
      curve.name = name;
      curve.point = point;
      curve.first_line = reader.line_number();
      curve.measured_depth = depth;
      curves.curves.push_back(curve);
    }
    IndentationCurve& curve = curves.curves[found->second];
    if ((curve.point - point).cwiseAbs().maxCoeff() > kSameCoordinateM) {
      reader.Fail("sample " + Quote(name) + " is at (" + fields[*column_x] + ", " +
                      fields[*column_y] + ", " + fields[*column_z] +
                      ") here but elsewhere on line " + std::to_string(curve.first_line),
                  "give each point its own name, and the same coordinates on all its rows");
    }
    if (column_depth && std::abs(curve.measured_depth - depth) > kSameCoordinateM) {
      reader.Fail("sample " + Quote(name) + " has depth " + fields[*column_depth] +
                      " here but another on line " + std::to_string(curve.first_line),
                  "give a point one measured depth on all its rows");
    }
    curve.indentation.push_back(indentation);
    curve.force.push_back(force);
  }
  if (!header_read) {
    throw InputError(path, "", "the file holds no header and no readings",
                     std::string("write a header row ") + kColumns + ", then one row per reading");
  }
  if (curves.curves.empty()) {
    throw InputError(path, "", "the file holds a header but no readings",
                     "write one row per reading after the header");
  }
  return curves;
}

}  // namespace ergo
