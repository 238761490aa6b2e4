// Per-vertex geometry of a triangle surface: barycentric vertex areas (one third of every
// incident triangle, the s_i of the paper's Eq. 12 and DESIGN.md §3) and their derivatives,
// and area-weighted vertex normals. Lengths in metres, areas in m².
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Area of each triangle (#F).
Eigen::VectorXd TriangleAreas(const TriMesh& mesh);

// s_i = Σ_{f ∋ i} area(f)/3 (#V); vertices in no triangle get 0.
Eigen::VectorXd BarycentricVertexAreas(const TriMesh& mesh);

// Gradient of one triangle's area with respect to its three corners, as a 3x3 matrix
// whose row k is ∂area/∂p_k. Zero for a degenerate triangle (the area is not
// differentiable there).
Eigen::Matrix3d TriangleAreaGradient(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& p2);

// Signed enclosed volume by the divergence theorem (Σ a·(b×c)/6 over the triangles): the
// volume of a closed surface, positive iff it is oriented outward. m³.
double EnclosedVolume(const TriMesh& mesh);

// Unit vertex normals: the area-weighted average of incident face normals (sum of the
// unnormalised cross products). A vertex in no (or only degenerate) triangles gets 0.
Vertices VertexNormals(const TriMesh& mesh);

}  // namespace ergo
