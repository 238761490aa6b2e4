#include "ergo/design/rigid_shape_gradient.h"

#include <glog/logging.h>

#include "ergo/design/adjoint_solve.h"
#include "ergo/ergonomics/score_gradient.h"

namespace ergo {

RigidShapeGradient RigidSupportShapeGradient(
    const TotalPotential& potential, const BodyState& state, const TotalPotential::Evaluation& e,
    const ContactPressures& pressures, const PressureScore& score, const TriMesh& support,
    const SparseCholesky& newton_factor, SparseCholesky* cholesky) {
  CHECK(!potential.soft_support()) << "a soft support's gradient is SoftSupportRestGradient";
  CHECK(score.has_partials) << "the adjoint needs ζ's partials (ScorePressures with_partials)";
  RigidShapeGradient out;
  SupportShapeGradient shape = score.partials.support;
  // Adjoint (Eq. 20): K̂ z = (∂ζ/∂y)ᵀ, then subtract zᵀ ∂G/∂x (Eq. 19).
  const Eigen::VectorXd rhs =
      potential.system().ReduceVertexGradient(state, e.positions, score.partials.body);
  if (rhs.squaredNorm() > 0) {
    const AdjointSolution adjoint = SolveAdjoint(e.hessian(), rhs, newton_factor, cholesky);
    out.pcg_iterations = adjoint.pcg_iterations;
    out.factorizations = adjoint.factorizations;
    if (!adjoint.ok) {
      out.message = adjoint.message;
      return out;
    }
    const Vertices velocity =
        potential.system().layout().VertexVelocity(potential.body(), state, e.positions, adjoint.z);
    const SupportShapeGradient contraction = ResidualShapeContraction(
        pressures.contacts, potential.body(), pressures.support_areas, velocity);
    shape.position -= contraction.position;
    shape.area -= contraction.area;
  }
  out.gradient = shape.position + ChainSupportAreas(shape.area, support);
  out.ok = true;
  out.message = "ok";
  return out;
}

}  // namespace ergo
