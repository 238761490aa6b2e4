#include "ergo/design/rest_shape_gradient.h"

#include <glog/logging.h>

#include "ergo/ergonomics/score_gradient.h"

namespace ergo {

RestShapeGradient SoftSupportRestGradient(const TotalPotential& potential, const BodyState& state,
                                          const TotalPotential::Evaluation& e,
                                          const PressureScore& score, SparseCholesky* cholesky) {
  CHECK(potential.soft_support()) << "a rest-shape gradient needs a soft support";
  const ElasticPart& part = *potential.soft_support();
  const ReducedLayout& layout = potential.layout();
  const Eigen::VectorXi& surface_to_part = part.boundary().surface_to_tet;
  CHECK(score.has_partials) << "the adjoint needs ζ's partials (ScorePressures with_partials)";
  const ScorePartials& partials = score.partials;

  // (∂ζ/∂y)ᵀ: the body's through B, the foam's free vertices' directly.
  Eigen::VectorXd rhs = potential.system().ReduceVertexGradient(state, e.positions, partials.body);
  const Eigen::Index offset = layout.support_offset();
  for (Eigen::Index i = 0; i < surface_to_part.size(); ++i) {
    const int f = part.free_index()[surface_to_part[i]];
    if (f >= 0) rhs.segment<3>(offset + 3 * f) += partials.support.position.row(i).transpose();
  }
  RestShapeGradient out;
  // ∂ζ/∂X: the score reads the foam's rest areas (its quadrature weights).
  const Vertices area_term = ChainSupportAreas(partials.support.area, part.boundary().surface);
  out.gradient = Vertices::Zero(part.rest().vertices.rows(), 3);
  for (Eigen::Index i = 0; i < surface_to_part.size(); ++i)
    out.gradient.row(surface_to_part[i]) += area_term.row(i);
  if (rhs.squaredNorm() > 0) {
    cholesky->AnalyzeIfChanged(e.hessian());
    const FactorizationStatus factor = cholesky->Factorize(e.hessian());
    if (!factor.ok) {
      out.message = "the exact Hessian at the equilibrium is not positive definite (" +
                    factor.message + "): dy/dX is undefined";
      return out;
    }
    const Eigen::VectorXd z = cholesky->Solve(rhs);
    out.gradient -= potential.RestShapeAdjoint(state, z, e);
  }
  out.ok = true;
  out.message = "ok";
  return out;
}

}  // namespace ergo
