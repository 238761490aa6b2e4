// A soft support's tet mesh from its closed surface (paper §4.3: the chair's cushion, the
// shoe's insole as foam): CGAL Mesh_3 of the solid the surface encloses, by the body
// builder's mesher (implicit_layer_mesher.h) with "inside the surface" as the region, fine
// at the top (where the body rests and the design acts) and graded coarser towards the base,
// and the base — the vertices on the lowest horizontal plane (y is up) — held. Mesh_3 follows
// the surface to a tenth of the edge length, so the solid's boundary rounds the surface's
// sharp edges at that scale; the contact surface is that boundary. Metres.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct SupportSolidOptions {
  double top_edge_length = 0.01;  // m, at the support's top
  double base_edge_length = 0;    // m, at its bottom (0: the top's); linear in height between
  unsigned seed = 0;              // CGAL's random choices (reproducible meshes)
  std::function<void(const std::string&)> progress;  // one line per stage
};

struct SupportSolid {
  TetMesh mesh;            // positively oriented
  std::vector<bool> base;  // per vertex: on the bottom plane, held
};

// Throws InputError naming `source` for a surface that is not closed and consistently
// oriented, for edge lengths that are not positive or would give more than 5 million tets,
// and for a surface with no horizontal bottom face to hold (give a vertex set instead).
SupportSolid MeshSupportSolid(const TriMesh& surface, const SupportSolidOptions& options,
                              const std::string& source);

// The vertices within `tolerance` of the lowest y (the held base of a support read from a
// user's tet mesh).
std::vector<bool> BottomVertices(const TetMesh& mesh, double tolerance);

}  // namespace ergo
