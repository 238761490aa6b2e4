// Self-intersections of a triangle surface: pairs of triangles that meet other than along
// a shared edge or vertex, found with CGAL Polygon Mesh Processing (exact predicates). This
// is the only translation unit of the mesh check that includes CGAL, so editing the rest
// never recompiles it. CGAL needs a combinatorial manifold; other meshes are skipped with
// the reason, which the caller reports.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct SelfIntersections {
  bool checked = false;                    // false: the test could not run, see skipped_because
  std::string skipped_because;             // e.g. "the surface is not manifold"
  std::vector<std::pair<int, int>> pairs;  // intersecting triangles (indices into the mesh)
  bool stopped_at_limit = false;           // more pairs than `max_pairs` exist
};

// Finds up to `max_pairs` pairs of intersecting triangles. Vertices must already be welded
// (coincident vertices merged), or touching neighbours count as intersecting. Triangles with
// a repeated vertex and collinear (degenerate) triangles are ignored here: the mesh check
// reports them itself.
SelfIntersections FindSelfIntersections(const TriMesh& mesh, int max_pairs);

}  // namespace ergo
