// A surface whose vertex is shared by two or more fans of triangles that meet only there (a
// "pinched" vertex: the core of a tissue layer where it narrows to a point, two sheets that
// touch) is not a 2-manifold, and halfedge structures (CGAL::Surface_mesh) refuse it. Giving
// each fan its own copy of the vertex makes the surface manifold at that vertex without
// moving anything: distances, areas and triangle indices are unchanged.
#pragma once

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// The surface with every pinched vertex split into one copy per fan (copies appended after
// the existing vertices; triangles keep their order). *split_count, if given, receives the
// number of copies added.
TriMesh SplitNonManifoldVertices(const TriMesh& surface, int* split_count = nullptr);

}  // namespace ergo
