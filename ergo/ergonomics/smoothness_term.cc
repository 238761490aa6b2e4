#include "ergo/ergonomics/smoothness_term.h"

namespace ergo {

SmoothnessValue EvaluateSmoothness(const Vertices& x, const SparseMatrix& laplacian,
                                   const TaubinParameters& taubin) {
  const Eigen::MatrixXd residual = Eigen::MatrixXd(x) - ApplyTaubin(laplacian, taubin, x);
  SmoothnessValue out;
  out.value = residual.squaredNorm();
  out.gradient = 2.0 * (residual - ApplyTaubinTransposed(laplacian, taubin, residual));
  return out;
}

}  // namespace ergo
