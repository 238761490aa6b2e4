// The adjoint system K̂ z = r of a design gradient (paper Eq. 20), K̂ the exact Hessian at the
// equilibrium: first by conjugate gradients preconditioned by Newton's factor (of K̂ at its
// last iterate, next to y*) where that is factorised, else by factorising K̂. Shared by the
// rigid and the soft support's shape gradients.
#pragma once

#include <string>

#include <Eigen/Core>

#include "ergo/mesh/eigen_types.h"
#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {

struct AdjointSolution {
  bool ok = false;
  std::string message;  // why not ok (K̂ not positive definite), or "ok"
  Eigen::VectorXd z;
  long pcg_iterations = 0;  // counted on failure too
  long factorizations = 0;  // 0 where PCG converged
};

// `cholesky` is (re)analysed on K̂'s pattern when it changed (a soft support's contact set).
AdjointSolution SolveAdjoint(const SparseMatrix& hessian, const Eigen::VectorXd& rhs,
                             const SparseCholesky& newton_factor, SparseCholesky* cholesky);

}  // namespace ergo
