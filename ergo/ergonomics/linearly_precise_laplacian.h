// The linearly precise Laplacian L̃ of a triangle surface with a boundary (Wang, Jacobson,
// Barbič & Kavan 2015, "Linear Subspace Design for Real-Time Shape Deformation", ACM TOG
// 34(4), §4): the weak Laplacian with its boundary term kept,
//   (L̃u)_i = ∫_Ω Δu φ_i = −(K u)_i + ∮_∂Ω (∇u·n) φ_i ,
// K the cotangent stiffness (ergo/mesh/cotangent_stiffness.h), the flux taken with each
// boundary triangle's constant gradient of u. The usual −K drops the flux (a zero-Neumann
// condition), so −K u ≠ 0 at the boundary vertices of a linear u and the squared Laplacian
// uᵀKM⁻¹Ku bends interpolants to meet the boundary at right angles. With the flux, L̃u = 0
// for every linear u on a planar mesh — exactly, since Σ_T ∫_T ∇φ_i = ∮ φ_i n along the
// boundary — so the energy uᵀ L̃ᵀ M⁻¹ L̃ u vanishes on linear functions. Dimensionless.
#pragma once

#include "ergo/mesh/eigen_types.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// N, #V x #V: (N u)_i = ∮_∂Ω (∇u·n) φ_i, summed over the boundary edges (edges of one
// triangle) at vertex i: (|e|/2) n_e·∇u|_T, n_e the unit outward normal of edge e in the
// plane of its triangle T. Zero rows at interior vertices; degenerate triangles add nothing.
SparseMatrix BoundaryFluxMatrix(const TriMesh& surface);

// L̃ = N − K (not symmetric at the boundary).
SparseMatrix LinearlyPreciseLaplacian(const TriMesh& surface);

}  // namespace ergo
