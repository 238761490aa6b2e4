// VTU (VTK XML unstructured grid, ASCII) output for ParaView: a triangle mesh
// (VTK_TRIANGLE cells) or a tetrahedral mesh (VTK_TETRA cells) with named per-vertex and
// per-cell scalar and vector fields. Coordinates and fields are written as given (SI), with
// the shortest decimals that read back exactly. Written atomically (temp file + rename).
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

struct VtuFields {
  std::vector<ScalarField> point_scalars;
  std::vector<VectorField> point_vectors;
  std::vector<ScalarField> cell_scalars;
  std::vector<VectorField> cell_vectors;
};

// Writes `mesh` and `fields`. Field sizes must match the mesh, names must be non-empty and
// every value finite (CHECKed: a wrong size or a NaN here is a bug in the caller). Throws
// InputError when the file cannot be written.
void WriteVtu(const std::string& path, const TriMesh& mesh, const VtuFields& fields = {});
void WriteVtu(const std::string& path, const TetMesh& mesh, const VtuFields& fields = {});

}  // namespace ergo
