#include "ergo/design/rest_shape_gradient.h"

#include <glog/logging.h>

#include "ergo/design/adjoint_solve.h"
#include "ergo/ergonomics/score_gradient.h"

namespace ergo {

RestShapeGradient SoftSupportRestGradient(const TotalPotential& potential, const BodyState& state,
                                          const TotalPotential::Evaluation& e,
                                          const PressureScore& score,
                                          const SparseCholesky& newton_factor,
                                          SparseCholesky* cholesky) {
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
    const AdjointSolution adjoint = SolveAdjoint(e.hessian(), rhs, newton_factor, cholesky);
    out.pcg_iterations = adjoint.pcg_iterations;
    out.factorizations = adjoint.factorizations;
    if (!adjoint.ok) {
      out.message = adjoint.message;
      return out;
    }
    out.gradient -= potential.RestShapeAdjoint(state, adjoint.z, e);
  }
  out.ok = true;
  out.message = "ok";
  return out;
}

}  // namespace ergo
