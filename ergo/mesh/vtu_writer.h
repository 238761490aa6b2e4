// VTU (VTK XML unstructured grid) output for ParaView: a triangle mesh (VTK_TRIANGLE cells)
// or a tetrahedral mesh (VTK_TETRA cells) with named per-vertex and per-cell scalar and
// vector fields. Coordinates and fields are written as given (SI) and read back bit for bit:
// by default as raw binary (Float64 values, Int64 connectivity and offsets, UInt8 cell types,
// little-endian, in one appended block): about half the ASCII file's size (the Int64 indices
// take as much room as their text) and a tenth of its write time (vtu_benchmark). ASCII
// (VtuEncoding::kAscii) writes the shortest decimals that read back exactly. Written
// atomically (temp file + rename).
//
//   VtuFields fields;
//   fields.point_scalars.push_back({"pressure_Pa", pressures});   // #V values
//   fields.cell_vectors.push_back({"normal", normals});           // #F x 3
//   WriteVtu("out/support.vtu", support, fields);
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct ScalarField {
  std::string name;
  Eigen::VectorXd values;  // one per vertex or per cell
};

struct VectorField {
  std::string name;
  Eigen::Matrix<double, Eigen::Dynamic, 3> values;  // one row per vertex or per cell
};

// How the arrays are stored in the file.
enum class VtuEncoding {
  // <AppendedData encoding="raw">: each array is its byte count (UInt64) followed by its
  // values, little-endian (header_type="UInt64", byte_order="LittleEndian"). The default.
  kBinary,
  // Each array's values as text inside its DataArray element (format="ascii").
  kAscii,
};

// "binary" or "ascii".
const char* VtuEncodingName(VtuEncoding encoding);
// Parses VtuEncodingName's words; false for anything else (`encoding` untouched).
bool ParseVtuEncoding(const std::string& text, VtuEncoding* encoding);

struct VtuFields {
  std::vector<ScalarField> point_scalars;
  std::vector<VectorField> point_vectors;
  std::vector<ScalarField> cell_scalars;
  std::vector<VectorField> cell_vectors;
};

// Writes `mesh` and `fields`. Field sizes must match the mesh, names must be non-empty and
// every value finite (CHECKed: a wrong size or a NaN here is a bug in the caller). Throws
// InputError when the file cannot be written.
void WriteVtu(const std::string& path, const TriMesh& mesh, const VtuFields& fields = {},
              VtuEncoding encoding = VtuEncoding::kBinary);
void WriteVtu(const std::string& path, const TetMesh& mesh, const VtuFields& fields = {},
              VtuEncoding encoding = VtuEncoding::kBinary);

}  // namespace ergo
