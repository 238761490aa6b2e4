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
  std::optional<CsvHeader> header;
  int column_sample = 0, column_x = 0, column_y = 0, column_z = 0, column_indentation = 0,
      column_force = 0;
  std::optional<int> column_depth;
  std::map<std::string, size_t> index_of;
  std::vector<std::string> fields;
  while (NextCsvRow(reader, &fields)) {
    if (!header) {
      header.emplace(
          reader, fields,
          std::vector<std::string>{"sample", "x", "y", "z", "indentation", "force", "depth"},
          kColumns);
      column_sample = header->Require(reader, "sample");
      column_x = header->Require(reader, "x");
      column_y = header->Require(reader, "y");
      column_z = header->Require(reader, "z");
      column_indentation = header->Require(reader, "indentation");
      column_force = header->Require(reader, "force");
      column_depth = header->Find("depth");
      curves.has_depth = column_depth.has_value();
      curves.ignored_columns = header->ignored();
      continue;
    }
    header->CheckRow(reader, fields);
    const std::string& name = fields[column_sample];
    if (name.empty())
      reader.Fail("the sample's name is empty", "name the measured point, e.g. heel_1");
    if (name.size() > kMaxNameLength)
      reader.Fail("the sample's name is longer than 128 characters", "use a short name");
    const Eigen::Vector3d point =
        metres * Eigen::Vector3d(ParseCsvNumber(reader, fields[column_x], "x"),
                                 ParseCsvNumber(reader, fields[column_y], "y"),
                                 ParseCsvNumber(reader, fields[column_z], "z"));
    const double indentation =
        metres * ParseCsvNumber(reader, fields[column_indentation], "indentation");
    const double force = ParseCsvNumber(reader, fields[column_force], "force");
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
      reader.Fail("sample " + Quote(name) + " is at (" + fields[column_x] + ", " +
                      fields[column_y] + ", " + fields[column_z] + ") here but elsewhere on line " +
                      std::to_string(curve.first_line),
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
  if (!header) {
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
