// Indentation measurements of soft tissue (paper §3.1), one force–indentation curve per
// measured point of the body part. The file is a CSV with one row per reading:
//
//   # any comment line starts with '#'
//   sample,x,y,z,indentation,force[,depth]
//   heel_1,0.012,0.004,-0.105,0.0005,0.021,0.017
//
// `sample` names the point; x, y, z place it on the skin (ergo's frame: y up) and
// `indentation` is the indenter's travel from first contact, all in the reader's length unit;
// `force` (compressive) is in newtons; `depth` (optional) is the layer's depth there,
// measured (by ultrasound, say) — the same on all rows of a sample. Readings before contact
// (δ ≤ 0) and a load cell's small negative readings near it are kept here; the fit leaves out
// δ ≤ 0. Rows of one sample may be interleaved with others' and must repeat its coordinates.
// Other columns (a time stamp) are ignored.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/length_unit.h"

namespace ergo {

struct IndentationCurve {
  std::string name;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m
  int first_line = 0;                               // 1-based line of its first reading
  std::vector<double> indentation;                  // m, in the file's order
  std::vector<double> force;                        // N
  double measured_depth = 0;                        // m; 0 when the file has no depth column
};

struct IndentationCurves {
  std::string source;  // the file
  bool has_depth = false;
  std::vector<IndentationCurve> curves;      // in order of first appearance
  std::vector<std::string> ignored_columns;  // header names that are not read
};

// Throws InputError naming the file, the line and the column for anything unusable: a
// missing column, a field that is not a finite number, a depth that is not positive, a
// sample whose coordinates or depth change between its rows.
IndentationCurves ReadIndentationCurvesCsv(const std::string& path, LengthUnit unit);

}  // namespace ergo
