// The dense symmetric matrix of a Hessian stored as its upper triangle (ergo's assemblies),
// for tests that compare it with finite differences or take its eigenvalues.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace ergo::testing {

inline Eigen::MatrixXd DenseSymmetric(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper) {
  const Eigen::MatrixXd u = Eigen::MatrixXd(upper);
  Eigen::MatrixXd full = u + u.transpose();
  full.diagonal() = u.diagonal();
  return full;
}

}  // namespace ergo::testing
