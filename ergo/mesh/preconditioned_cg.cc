#include "ergo/mesh/preconditioned_cg.h"

#include <cmath>

#include <glog/logging.h>

namespace ergo {

PcgResult PreconditionedConjugateGradient(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
    const SparseCholesky& preconditioner, const Eigen::VectorXd& b, double tolerance,
    int max_iterations) {
  CHECK(preconditioner.factorized());
  CHECK_EQ(upper.rows(), b.size());
  PcgResult result;
  result.x = Eigen::VectorXd::Zero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0) {
    result.converged = true;
    return result;
  }
  const auto a = upper.selfadjointView<Eigen::Upper>();
  Eigen::VectorXd r = b;
  Eigen::VectorXd z = preconditioner.Solve(r);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  for (int k = 0; k < max_iterations; ++k) {
    const Eigen::VectorXd ap = a * p;
    const double curvature = p.dot(ap);
    if (!(curvature > 0)) {
      result.negative_curvature = true;
      break;
    }
    const double step = rz / curvature;
    result.x += step * p;
    r -= step * ap;
    result.iterations = k + 1;
    result.relative_residual = r.norm() / b_norm;
    if (result.relative_residual <= tolerance) {
      result.converged = true;
      break;
    }
    z = preconditioner.Solve(r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

}  // namespace ergo
