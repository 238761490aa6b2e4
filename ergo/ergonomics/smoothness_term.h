// The smoothness regulariser of paper Eq. 14: ψ(x) = ‖x − T^m x‖² over the support's vertex
// positions, T = (I − μL)(I − λL) Taubin smoothing with the umbrella Laplacian, and its
// gradient 2 (I − T^m)ᵀ (I − T^m) x. Units: m².
#pragma once

#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct SmoothnessValue {
  double value = 0;   // ψ, m²
  Vertices gradient;  // ∂ψ/∂x per support vertex, m
};

// ψ and its gradient at support positions `x` (#V x 3) with the support's Laplacian.
SmoothnessValue EvaluateSmoothness(const Vertices& x, const SparseMatrix& laplacian,
                                   const TaubinParameters& taubin);

}  // namespace ergo
