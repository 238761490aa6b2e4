// Derivatives of one tet's elastic energy and forces with respect to its rest positions X:
// the ∂f_int/∂X of the paper's rest-shape design (§4.3, Eq. 22–23), where a soft support's
// rest shape is the design and the adjoint needs how the equilibrium residual moves with it.
//
// With E = V ψ(F), F = Ds Dm⁻¹, the rest shape enters through V = det(Dm)/6 and W = Dm⁻¹:
//   dW = −W dDm W,   dF = Ds dW = −F dDm W,   dV = V tr(W dDm),
// and the force on corner v, f_v = ∂E/∂x_v = V P G_v (G_v = row v of the shape gradients),
//   df_v = dV P G_v + V (∂P/∂F : dF) G_v + V P dG_v,
// with the exact ∂P/∂F (the residual's true derivative; a PSD projection would be wrong
// here). Units: J/m for ∂E/∂X, N/m for ∂f/∂X.
#pragma once

#include "ergo/material/neo_hookean.h"
#include "ergo/material/tet_element.h"

namespace ergo {

// ∂E/∂X: the energy's derivative with respect to the 12 rest coordinates (corner-major), J/m.
// `rest` must be a positively oriented tet (CHECKed).
Vector12d ElementEnergyRestGradient(const NeoHookean& material, const TetPositions& rest,
                                    const TetPositions& x);

// ∂(∂E/∂x)/∂X: column j is the change of the 12 corner forces per unit of rest coordinate j,
// N/m. The mixed second derivative: ∂²E/∂x∂X, not symmetric.
Matrix12d ElementForceRestJacobian(const NeoHookean& material, const TetPositions& rest,
                                   const TetPositions& x);

// d V/dX for the rest volume V = det(Dm)/6 (lumped masses depend on it), m².
Vector12d TetVolumeRestGradient(const TetPositions& rest);

}  // namespace ergo
