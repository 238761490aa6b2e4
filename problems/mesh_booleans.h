// Boolean operations and remeshing of closed triangle surfaces for the scenario generators
// (paper §3.2: the mouse is the CSG union of two spheres; §5.1: the negative-image chair is
// the support minus the body by CSG subtraction), by CGAL Polygon Mesh Processing
// corefinement and isotropic remeshing. Metres. CGAL stays inside mesh_booleans.cc (slow to
// compile).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct BooleanResult {
  // Closed, outward, compact vertex numbering. Along the cut the corefinement leaves slivers
  // and, where the curve passes (nearly) through input vertices, zero-area triangles:
  // remesh the cut's neighbourhood (RemeshIsotropic) before using the result as a support.
  TriMesh mesh;
  // The intersection curve of the two inputs as segments (endpoints in metres): where the
  // result has sharp edges that the scenario may want to smooth.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> cut;
};

// The surface of the union of the volumes bounded by `a` and `b`. Throws InputError naming
// `source` when an input does not bound a volume (open, self-intersecting, inconsistently
// oriented) or the result is not a manifold surface.
BooleanResult MeshUnion(const TriMesh& a, const TriMesh& b, const std::string& source);

// The surface of the volume of `a` minus the volume of `b` (same errors).
BooleanResult MeshDifference(const TriMesh& a, const TriMesh& b, const std::string& source);

// Isotropic remeshing (CGAL: split, collapse, flip, tangential relaxation, projection onto
// the input) of the triangles flagged in `faces` (empty = all) towards edges of
// `target_edge_length` metres; the boundary of the flagged region stays where it is.
TriMesh RemeshIsotropic(const TriMesh& mesh, const std::vector<bool>& faces,
                        double target_edge_length, int iterations);

}  // namespace ergo
