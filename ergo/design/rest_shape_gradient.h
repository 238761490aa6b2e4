// The score's gradient with respect to a soft support's rest shape (paper §4.3, Eq. 21–23):
// at an equilibrium y* of body and foam, dζ/dX = ∂ζ/∂X − zᵀ ∂G/∂X with the adjoint K̂ z =
// (∂ζ/∂y)ᵀ, where y holds the foam's displacements too and both partials are taken with
// every deformed position fixed (so the held base, whose positions are its rest positions,
// is not designed). ∂ζ/∂X is the foam's rest vertex areas' share (its contact quadrature and
// score weights, ChainSupportAreas); zᵀ∂G/∂X is TotalPotential::RestShapeAdjoint (element
// forces, weight, support springs' areas). A design space pulls it back through its own map
// (RestExtension for the interior, then the top's parameterisation).
#pragma once

#include <string>

#include "ergo/equilibrium/total_potential.h"
#include "ergo/ergonomics/pressure_score.h"
#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {

struct RestShapeGradient {
  bool ok = false;
  std::string message;      // why not ok (K̂ not positive definite), or "ok"
  Vertices gradient;        // dζ/dX per foam vertex (#V_support x 3), Pa^e·m²/m
  long pcg_iterations = 0;  // the adjoint solve's work (SolveAdjoint), on failure too
  long factorizations = 0;
};

// `e`: the evaluation at `state` with the exact K̂ (TotalPotential::Evaluate with
// HessianKind::kExact and the contact Hessians); `score`: ζ of its contacts' pressures with
// its partials (ScorePressures with_partials; which halves ζ holds is the score's).
// The adjoint is solved by SolveAdjoint (adjoint_solve.h) with `newton_factor` and `cholesky`.
RestShapeGradient SoftSupportRestGradient(const TotalPotential& potential, const BodyState& state,
                                          const TotalPotential::Evaluation& e,
                                          const PressureScore& score,
                                          const SparseCholesky& newton_factor,
                                          SparseCholesky* cholesky);

}  // namespace ergo
