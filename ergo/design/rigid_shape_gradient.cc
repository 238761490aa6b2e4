#include "ergo/design/rigid_shape_gradient.h"

#include <glog/logging.h>

#include "ergo/ergonomics/score_gradient.h"
#include "ergo/mesh/preconditioned_cg.h"

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
    Eigen::VectorXd z;
    if (newton_factor.factorized()) {
      const PcgResult cg =
          PreconditionedConjugateGradient(e.hessian(), newton_factor, rhs, 1e-12, 30);
      out.pcg_iterations += cg.iterations;
      if (cg.converged) z = cg.x;
    }
    if (z.size() == 0) {
      const FactorizationStatus factor = cholesky->Factorize(e.hessian());
      ++out.factorizations;
      if (!factor.ok) {
        out.message = "the exact Hessian at the equilibrium is not positive definite (" +
                      factor.message +
                      "): the equilibrium is not a strict minimum, so dy/dx is undefined";
        return out;
      }
      z = cholesky->Solve(rhs);
    }
    const Vertices velocity =
        potential.system().layout().VertexVelocity(potential.body(), state, e.positions, z);
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
