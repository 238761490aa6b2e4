#include "ergo/ergonomics/pressure_plate_csv.h"

#include <cmath>
#include <sstream>

#include "ergo/ergonomics/csv_row.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

// Plates and in-shoe systems have at most a few hundred cells per side; a larger matrix is
// another kind of file.
constexpr size_t kMaxCellsPerSide = 4096;

struct UnitEntry {
  const char* name;
  double pascals;
};
constexpr UnitEntry kUnits[] = {{"Pa", 1.0},
                                {"kPa", 1e3},
                                {"MPa", 1e6},
                                {"N/cm2", 1e4},
                                {"mmHg", 133.322387415},
                                {"psi", 6894.757293168}};

std::string Trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
    text.remove_suffix(1);
  return std::string(text);
}

}  // namespace

bool PascalsPerUnit(const std::string& unit, double* pascals) {
  for (const UnitEntry& entry : kUnits) {
    if (ToLower(unit) == ToLower(entry.name)) {
      *pascals = entry.pascals;
      return true;
    }
  }
  return false;
}

std::string PressureUnitNames() {
  std::string names;
  for (const UnitEntry& entry : kUnits)
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

PressurePlateReading ReadPressurePlateCsv(const std::string& path, const PlateCsvOptions& options,
                                          const std::string& pitch_option,
                                          const std::string& unit_option) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  PressurePlateReading reading;
  double file_pitch_mm = 0;
  std::string file_unit;
  std::vector<std::vector<double>> rows;
  std::string_view line;
  while (reader.NextLine(&line)) {
    reader.RequireRecordLength(line);
    const std::string content = Trimmed(line);
    if (content.empty()) continue;
    if (content[0] == '#') {
      const std::string comment = Trimmed(std::string_view(content).substr(1));
      const size_t equals = comment.find('=');
      if (equals == std::string::npos) continue;
      const std::string key = ToLower(Trimmed(std::string_view(comment).substr(0, equals)));
      const std::string value = Trimmed(std::string_view(comment).substr(equals + 1));
      if (key == "pitch_mm") {
        if (!ParseDouble(value, &file_pitch_mm) || !std::isfinite(file_pitch_mm) ||
            !(file_pitch_mm > 0)) {
          reader.Fail("pitch_mm " + Quote(value) + " is not a positive number of millimetres",
                      "write e.g. '# pitch_mm=5.08', or give --" + pitch_option);
        }
        reading.pitch_source = reader.Location() + " of " + path;
      } else if (key == "unit") {
        double pascals = 0;
        if (!PascalsPerUnit(value, &pascals)) {
          reader.Fail("unit " + Quote(value) + " is not one ergo reads",
                      "write one of " + PressureUnitNames() + ", or give --" + unit_option);
        }
        file_unit = value;
        reading.unit_source = reader.Location() + " of " + path;
      }
      continue;
    }
    const std::vector<std::string> fields = SplitCsvRow(content);
    if (fields.size() > kMaxCellsPerSide)
      reader.Fail("more than 4096 cells in a row", "give one row of plate cells per line");
    if (!rows.empty() && fields.size() != rows.front().size()) {
      reader.Fail("has " + std::to_string(fields.size()) + " cells, the first row " +
                      std::to_string(rows.front().size()),
                  "every row of the plate must have the same number of cells (write 0 for an "
                  "unloaded cell)");
    }
    if (rows.size() >= kMaxCellsPerSide)
      reader.Fail("more than 4096 rows of cells", "give one row of plate cells per line");
    std::vector<double> row(fields.size());
    for (size_t c = 0; c < fields.size(); ++c) {
      const std::string where = reader.Location() + ", cell " + std::to_string(c + 1);
      if (fields[c].empty())
        throw InputError(path, where, "the cell is empty", "write 0 for an unloaded cell");
      if (!ParseDouble(fields[c], &row[c])) {
        throw InputError(path, where, Quote(fields[c]) + " is not a number",
                         "write plain decimal numbers with '.' as the decimal point (no units "
                         "in the cells: the unit goes in '# unit=kPa')");
      }
      if (!std::isfinite(row[c]))
        throw InputError(path, where, Quote(fields[c]) + " is not finite",
                         "write a finite pressure");
      if (row[c] < 0) {
        throw InputError(path, where, "the pressure " + fields[c] + " is negative",
                         "contact pressures are >= 0: write 0 for cells below the plate's "
                         "threshold");
      }
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) {
    throw InputError(path, "", "the file holds no rows of cell pressures",
                     "write the plate's matrix, one row of cells per line");
  }

  if (options.pitch_mm > 0) {
    reading.pitch_source = "--" + pitch_option;
    reading.grid.pitch = 1e-3 * options.pitch_mm;
  } else if (file_pitch_mm > 0) {
    reading.grid.pitch = 1e-3 * file_pitch_mm;
  } else {
    throw InputError(
        path, "", "the cell pitch is not given",
        "add a line '# pitch_mm=5.08' (the plate's sensor spacing) or give --" + pitch_option);
  }
  if (!options.unit.empty()) {
    reading.unit = options.unit;
    reading.unit_source = "--" + unit_option;
  } else if (!file_unit.empty()) {
    reading.unit = file_unit;
  } else {
    reading.unit = "kPa";
    reading.unit_source = "default (kPa: neither a '# unit=' line nor --" + unit_option + ")";
  }
  double pascals = 0;
  if (!PascalsPerUnit(reading.unit, &pascals)) {
    throw InputError("--" + unit_option, "",
                     Quote(reading.unit) + " is not a pressure unit ergo reads",
                     "use one of " + PressureUnitNames());
  }
  const auto row_count = static_cast<Eigen::Index>(rows.size());
  const auto column_count = static_cast<Eigen::Index>(rows.front().size());
  reading.grid.pressure.resize(row_count, column_count);
  for (Eigen::Index r = 0; r < row_count; ++r)
    for (Eigen::Index c = 0; c < column_count; ++c)
      reading.grid.pressure(r, c) = pascals * rows[static_cast<size_t>(r)][static_cast<size_t>(c)];
  if (!(reading.grid.pressure.maxCoeff() > 0)) {
    throw InputError(path, "", "every cell reads 0: nothing was measured",
                     "export the frame (or the average of frames) in which the foot stands on "
                     "the plate");
  }
  return reading;
}

void WritePressurePlateCsv(const std::string& path, const PressureGrid& grid,
                           const std::string& unit, const std::vector<std::string>& comment) {
  double pascals = 0;
  if (!PascalsPerUnit(unit, &pascals))
    throw InputError(path, "", "unit " + Quote(unit) + " is not one ergo writes",
                     "use one of " + PressureUnitNames());
  WriteFileAtomically(path, [&](std::ostream& out) {
    for (const std::string& line : comment) out << "# " << line << "\n";
    out << "# pitch_mm=";
    WriteDouble(out, 1e3 * grid.pitch);
    out << "\n# unit=" << unit << "\n";
    for (Eigen::Index r = 0; r < grid.rows(); ++r) {
      for (Eigen::Index c = 0; c < grid.columns(); ++c) {
        if (c > 0) out << ",";
        WriteDouble(out, grid.pressure(r, c) / pascals);
      }
      out << "\n";
    }
  });
}

}  // namespace ergo
