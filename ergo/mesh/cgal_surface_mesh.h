// TriMesh ⇄ CGAL::Surface_mesh for the CGAL translation units (Polygon Mesh Processing,
// AABB trees). A fresh conversion keeps the numbering: vertex v and triangle f of the
// TriMesh are the Surface_mesh's vertex v and face f. Templated on the CGAL point type and
// instantiated for the two kernels ergo uses: Exact_predicates_inexact_constructions_kernel
// (Booleans, hole filling, remeshing: exact predicates) and Simple_cartesian<double>
// (distance queries, which need none). This header pulls in CGAL's Surface_mesh: include it
// only from the .cc files that work on one, never from a stage's public header.
//
//   using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
//   CGAL::Surface_mesh<Point> surface = ToSurfaceMesh<Point>(mesh, path);
//   ... CGAL::Polygon_mesh_processing on `surface` ...
//   TriMesh result = FromSurfaceMesh(surface);
#pragma once

#include <string>

#include <CGAL/Surface_mesh.h>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// The surface with vertex v at mesh.vertices.row(v) and face f = mesh.triangles.row(f).
// Throws InputError(source, "<which> triangle f", ...) for the first triangle that cannot be
// joined to its neighbours (a non-manifold edge or vertex, or an orientation opposite to a
// neighbour's); `which` names the mesh among several ("first operand"), "" for none.
// Vertex indices out of range are a programming error (CHECK).
template <typename Point>
CGAL::Surface_mesh<Point> ToSurfaceMesh(const TriMesh& mesh, const std::string& source,
                                        const std::string& which = "");

// The surface's live vertices, renumbered 0.. in index order (removed ones skipped, so a
// surface without removals keeps its numbering), and its faces in index order. Every face
// must be a triangle (CHECK).
template <typename Point>
TriMesh FromSurfaceMesh(const CGAL::Surface_mesh<Point>& surface);

}  // namespace ergo
