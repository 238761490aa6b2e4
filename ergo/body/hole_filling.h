// Closing an open scan (paper §3.1: only the region of interest of the body is scanned, so
// the surface ends at a cut): every boundary loop of a manifold, consistently oriented
// triangle surface gets a flat cap, and the result is checked to be closed, free of
// self-intersections and oriented outward. Metres. CGAL stays inside hole_filling.cc.
#pragma once

#include <string>
#include <vector>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct CappedSurface {
  TriMesh surface;                 // closed, outward; input vertices and triangles first
  int holes_capped = 0;            // boundary loops closed
  int cap_triangles = 0;           // triangles added (the last rows of surface.triangles)
  std::vector<std::string> notes;  // one line per cap: size, planarity
};

// Caps each boundary loop of `surface` (a 2-D constrained Delaunay triangulation in the
// loop's best-fit plane when the loop is nearly planar, CGAL's minimal-weight patch
// otherwise), then reverses all faces if the enclosed volume is negative. Throws
// InputError naming `source` when the surface is not a manifold the caps can attach to,
// or when a cap intersects the surface (a loop that is no cut). A closed input is
// returned unchanged (up to orientation).
CappedSurface CloseWithFlatCaps(const TriMesh& surface, const std::string& source);

}  // namespace ergo
