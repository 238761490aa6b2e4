// Boundary surface of a tetrahedral mesh: the triangles that belong to exactly one tet,
// oriented outward, as a compact TriMesh with maps between surface and tet vertices.
// The body's skin and its core interface are both taken from this surface.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct TetBoundary {
  TriMesh surface;                  // compact: only boundary vertices, outward faces
  Eigen::VectorXi surface_to_tet;   // surface vertex -> tet-mesh vertex
  Eigen::VectorXi tet_to_surface;   // tet-mesh vertex -> surface vertex, or -1
  Eigen::VectorXi face_tet;         // the tet each boundary face belongs to
  std::vector<int> face_component;  // connected component of each face (edge-connected)
  int component_count = 0;
};

// Faces shared by two tets are interior; faces used once form the boundary. Faces used
// three or more times (a non-manifold tet mesh) are a programming error here: the mesh
// check reports them to users first. Tets must be positively oriented.
TetBoundary ExtractBoundary(const TetMesh& mesh);

}  // namespace ergo
