// Conjugate gradients on a symmetric matrix (upper triangle stored), preconditioned by the
// Cholesky factorisation of a nearby matrix — the factor of an earlier Newton step or of
// the previous design's equilibrium. A solve with an existing factor costs a fraction of a
// new factorisation, so Newton steps and adjoint solves reuse factors while PCG converges
// in a few iterations, and refactorise only when it does not (DESIGN.md §7).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {

struct PcgResult {
  Eigen::VectorXd x;
  int iterations = 0;
  double relative_residual = 0;  // ‖b − A x‖ / ‖b‖
  bool converged = false;
  bool negative_curvature = false;  // pᵀ A p ≤ 0 met: A is not positive definite
};

// Solves A x = b to ‖b − A x‖ ≤ tolerance ‖b‖ within max_iterations; `preconditioner` must
// hold a successful factorisation of a matrix of the same size.
PcgResult PreconditionedConjugateGradient(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
    const SparseCholesky& preconditioner, const Eigen::VectorXd& b, double tolerance,
    int max_iterations);

}  // namespace ergo
