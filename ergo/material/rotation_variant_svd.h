// Rotation-variant ("signed") singular value decomposition of a 3x3 deformation
// gradient, F = U diag(sigma) V^T with U and V proper rotations (det = +1). The
// stretches are sorted sigma1 >= sigma2 >= |sigma3|, and sigma3 < 0 exactly when
// det F < 0 (an inverted tetrahedron). This is the decomposition of invertible FEM
// (Irving et al. 2004); see ergo/material/README.md §2. Dimensionless.
#pragma once

#include <Eigen/Core>

namespace ergo {

// F = u * sigma.asDiagonal() * v^T.
struct SignedSvd3 {
  Eigen::Matrix3d u;      // proper rotation, columns are the left singular vectors
  Eigen::Vector3d sigma;  // principal stretches, sigma(0) >= sigma(1) >= |sigma(2)|
  Eigen::Matrix3d v;      // proper rotation, columns are the right singular vectors
};

// Signed SVD of a finite F; backward stable (|F - U S V^T| ~ 1e-15 |F|) and with high
// relative accuracy for well-separated small stretches. Allocation-free, ~230 ns.
// Rank-deficient F is handled (the null directions get an arbitrary orthonormal frame).
SignedSvd3 RotationVariantSvd(const Eigen::Matrix3d& f);

}  // namespace ergo
