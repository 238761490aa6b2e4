// The score's gradient with respect to a rigid support's surface (paper §4.3, Eq. 17–20): at
// an equilibrium y* of the body on the support x, dζ/dx = ∂ζ/∂x − zᵀ ∂G/∂x with the adjoint
// K̂ z = (∂ζ/∂y)ᵀ, G = ∂E/∂y the equilibrium residual. ∂ζ/∂y and ∂ζ/∂x are the score's
// explicit partials (ergo/ergonomics/pressure_score.h); zᵀ∂G/∂x is ResidualShapeContraction;
// the vertex-area parts are chained through ∂s_j/∂x once at the end. A design space pulls it
// back through its own map. The soft support's counterpart is rest_shape_gradient.h.
#pragma once

#include <string>

#include "ergo/equilibrium/total_potential.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/pressure_score.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct RigidShapeGradient {
  bool ok = false;
  std::string message;  // why not ok (K̂ not positive definite), or "ok"
  Vertices gradient;    // dζ/dx per support vertex (#S x 3), Pa^e·m²/m
  // The adjoint solve's work, for EvaluationTiming (counted on failure too).
  long pcg_iterations = 0;  // conjugate gradients preconditioned by the Newton factor
  long factorizations = 0;  // fresh factorisations of K̂ (0 where PCG converged)
};

// `e`: the evaluation at `state` with the exact K̂ and the contact Hessians; `pressures`: the
// score's pressures of e's contacts; `score`: ζ with its partials (has_partials); `support`:
// the support surface at the design (the shape `pressures.support_areas` were taken on).
// The adjoint is solved by SolveAdjoint (adjoint_solve.h) with `newton_factor` and
// `cholesky`.
RigidShapeGradient RigidSupportShapeGradient(
    const TotalPotential& potential, const BodyState& state, const TotalPotential::Evaluation& e,
    const ContactPressures& pressures, const PressureScore& score, const TriMesh& support,
    const SparseCholesky& newton_factor, SparseCholesky* cholesky);

}  // namespace ergo
