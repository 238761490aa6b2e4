// TriMesh and TetMesh: the two mesh types every stage exchanges. Plain Eigen matrices,
// one row per vertex / element, row-major so that a mesh's vertex block is a flat
// (x0,y0,z0,x1,...) vector in memory. Coordinates are in metres (SI) once read.
#pragma once

#include <Eigen/Core>

namespace ergo {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Tetrahedra = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

// A triangle surface. Faces are counter-clockwise seen from outside (outward normals).
struct TriMesh {
  Vertices vertices;    // #V x 3, metres
  Triangles triangles;  // #F x 3, 0-based vertex indices
};

// A linear tetrahedral mesh. Positive orientation: (v1-v0)·((v2-v0)×(v3-v0)) > 0.
struct TetMesh {
  Vertices vertices;  // #V x 3, metres
  Tetrahedra tets;    // #T x 4, 0-based vertex indices
};

}  // namespace ergo
