// The derivatives of the pressure score ζ (paper Eq. 11–12) that the adjoint gradient
// (Eq. 17–20) chains, for the two-way area-weighted contact of
// ergo/contact/surface_contact.h. ζ = Σ s P̄^e over both surfaces with p_v = κ g_v = L_v/s_v,
// L_v = ‖f_v‖/share the load of vertex v's own spring (force f_v = −∂E/∂p_v; share α on
// the skin, 1 − α on the support), so
//   ∂ζ/∂z = Σ_springs −(w_v/share) f̂_vᵀ ∂²E/∂p_v∂z,  w_v = ∂ζ/∂L_v,
// for z every variable of the spring (its point and its anchor feature's vertices, on the
// body or the support). A support vertex's spring stiffness k = ½κ(1 − α) s_j(x) (so its load)
// and its pressure's denominator s_j(x) make ζ depend on the support's shape through the
// vertex areas too; those terms are collected as per-vertex weights ∂ζ/∂s_j and chained
// through ∂s_j/∂x once (ChainSupportAreas).
// Units: ζ in Pa^e·m², positions m.
#pragma once

#include <Eigen/Core>

#include "ergo/body/layered_body.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// A gradient with respect to the support's shape, split into the part through the vertex
// positions directly and the part through the barycentric vertex areas s_j(x).
struct SupportShapeGradient {
  Vertices position;     // #S x 3
  Eigen::VectorXd area;  // #S: ∂/∂s_j
};

// The explicit partial derivatives of ζ at an equilibrium: with respect to the body's
// vertex positions (#V x 3, the adjoint's right-hand side before reduction) and to the
// support's shape (at fixed body state).
struct ScorePartials {
  Vertices body;
  SupportShapeGradient support;
};

// ∂ζ/∂(body positions) and ∂ζ/∂(support shape) from the pressures' contact springs (their
// Hessians must have been evaluated). `support_side` false: of ζ's skin side alone
// (DesignOptions::score_support_side).
ScorePartials PressureScorePartials(const ContactPressures& pressures, const LayeredBody& body,
                                    bool support_side = true);

// zᵀ ∂G/∂x, the adjoint contraction (Eq. 19): G = ∂E/∂y the equilibrium residual, whose
// contact part depends on the support through the springs' feature positions, points and
// (support springs) stiffnesses; `body_velocity` = the vertex displacement field of the
// adjoint solution z (ReducedLayout::VertexVelocity), #V x 3.
SupportShapeGradient ResidualShapeContraction(const SurfaceContacts& contacts,
                                              const LayeredBody& body,
                                              const Eigen::VectorXd& support_areas,
                                              const Vertices& body_velocity);

// (∂G/∂x)·δx in vertex space: how the contact forces on the body's vertices change when the
// support's vertices move by `support_velocity` (#S x 3) at fixed body state — the forward
// product of the contraction above (through the springs' cross blocks and the support
// springs' area-dependent stiffness). #V x 3; the caller reduces it to y.
Vertices ResidualShapeDerivative(const SurfaceContacts& contacts, const LayeredBody& body,
                                 const TriMesh& support, const Vertices& support_velocity);

// Σ_j w_j ∂s_j/∂x for barycentric vertex areas s_j of `support`: #S x 3.
Vertices ChainSupportAreas(const Eigen::VectorXd& area_weight, const TriMesh& support);

}  // namespace ergo
