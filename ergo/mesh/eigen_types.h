// The fixed-size and sparse Eigen types every stage's signatures use: per-element vectors
// and matrices over 2, 3 or 4 stacked 3-vectors (a point and a feature's vertices, a tet's
// corners), and the one sparse matrix type (column-major, int indices: CHOLMOD's layout).
// Declared once here so that the stages' headers cannot disagree on them.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace ergo {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector9d = Eigen::Matrix<double, 9, 1>;
using Vector12d = Eigen::Matrix<double, 12, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace ergo
