// A pressure plate's export as ergo reads and writes it: the cell pressures as a matrix, one
// row of cells per line — the usual ASCII export of plate and in-shoe systems — with the cell
// pitch and unit in comment lines:
//
//   # pitch_mm=5.08
//   # unit=kPa
//   0,0,1.2,3.4,0
//   0,2.5,41.0,37.2,1.1
//
// Cells are separated by commas, semicolons, tabs or blanks; '.' is the decimal point. Lines
// starting with '#' are comments; `# pitch_mm=H` and `# unit=U` in them give the pitch (mm)
// and the unit: Pa, kPa, MPa, N/cm2, mmHg or psi. Options (ergo_validate's --plate_pitch,
// --plate_unit) override both. The matrix as printed is the plate seen from above with +x to
// the right: the first line is the row at the smallest z and rows run along +z (PressureGrid's
// frame); a mirrored export cannot be aligned by a rigid motion. Pressures must be finite and
// not negative. Read into Pa and metres.
#pragma once

#include <string>
#include <vector>

#include "ergo/ergonomics/pressure_grid.h"

namespace ergo {

struct PlateCsvOptions {
  double pitch_mm = 0;  // > 0 overrides the file's pitch_mm
  std::string unit;     // not empty: overrides the file's unit
};

struct PressurePlateReading {
  PressureGrid grid;  // Pa, m
  std::string unit;   // as read, e.g. "kPa"
  // Where the pitch and the unit came from, for the report: "line 2 of FILE", "--plate_pitch"
  // (the option), or for the unit "default (kPa)" when neither file nor option gives one.
  std::string pitch_source, unit_source;
};

// Pascals per one `unit` (case-insensitive: pa, kpa, mpa, n/cm2, mmhg, psi). false for
// anything else.
bool PascalsPerUnit(const std::string& unit, double* pascals);
// "Pa, kPa, MPa, N/cm2, mmHg, psi", for messages.
std::string PressureUnitNames();

// Throws InputError naming the file, the line and the cell (or the option) for anything
// unusable; `pitch_option` and `unit_option` name options.pitch_mm and options.unit there.
PressurePlateReading ReadPressurePlateCsv(const std::string& path, const PlateCsvOptions& options,
                                          const std::string& pitch_option = "pitch_mm",
                                          const std::string& unit_option = "unit");

// Writes `grid` in `unit` (atomically), `comment` lines first (each prefixed with "# "), then
// the pitch and unit lines and the matrix. The grid's origin is not written (a plate's frame
// starts at its first cell's corner).
void WritePressurePlateCsv(const std::string& path, const PressureGrid& grid,
                           const std::string& unit, const std::vector<std::string>& comment);

}  // namespace ergo
