// The cotangent stiffness matrix K of a triangle surface: the P1 finite-element Laplacian,
// K_ij = ∫ ∇φ_i·∇φ_j = −½ (cot α_ij + cot β_ij) for an edge ij (α, β the angles opposite it),
// K_ii = −Σ_j K_ij. Symmetric, positive semi-definite, rows summing to 0; xᵀKx = ∫|∇x|² of
// the piecewise-linear field x (exact for linear fields on planar pieces). Dimensionless.
// With the lumped mass (BarycentricVertexAreas, surface_geometry.h) it gives the Helmholtz
// filter of SupportParameterization (DESIGN.md §8).
#pragma once

#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// K, #V x #V, over `triangles` (#F x 3 indices into `vertices`, #V x 3, metres). Vertices in
// no triangle get an all-zero row and column. A degenerate (zero-area) triangle contributes
// nothing: its cotangents are unbounded while its ∫|∇x|² term has no area to live on.
SparseMatrix CotangentStiffness(const Triangles& triangles, const Vertices& vertices);

}  // namespace ergo
