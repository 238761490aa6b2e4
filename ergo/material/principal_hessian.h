// The second derivative of an isotropic energy density in the principal frame of F
// (Teran et al. 2005; Smith et al. 2019): a 3x3 block on the principal stretches and one
// 2x2 block per pair of stretches, and its rotation back to dP/dF (9x9, Pa) or, through
// the linear tet's dF/dx, to the 12x12 element Hessian (N/m). See README §4 and §6.
#pragma once

#include <Eigen/Core>

#include "ergo/material/rotation_variant_svd.h"
#include "ergo/mesh/eigen_types.h"

namespace ergo {

// vec(F) ordering of every Vector9d and Matrix9d in ergo/material: column-major,
// vec(F)[a + 3 b] = F(a, b) (Eigen's storage order for Matrix3d).

// d2psi/dF2 in the frame F = U diag(sigma) V^T, in Pa: the 3x3 block d2psi/dsigma2 and,
// for each pair (i, j) in the order (0,1), (0,2), (1,2), the two eigenvalues of its 2x2
// block [[A, B], [B, A]] acting on the (ij, ji) entries of U^T dF V:
//   difference_quotient = A + B = (psi_i - psi_j) / (sigma_i - sigma_j), mode (1, 1),
//   sum_quotient        = A - B = (psi_i + psi_j) / (sigma_i + sigma_j), mode (1, -1).
struct PrincipalHessian {
  Eigen::Matrix3d stretch_block;
  Eigen::Vector3d difference_quotient;
  Eigen::Vector3d sum_quotient;
};

// dP/dF (9x9, vec ordering above) = (V (x) U) K (V (x) U)^T with K the principal blocks.
Matrix9d StressDerivativeFromPrincipal(const SignedSvd3& svd, const PrincipalHessian& h);

// volume * D^T (dP/dF) D for a linear tet, D = dvec(F)/dx, with shape_gradients the 4x3
// matrix G of dF_ab/dx_vc = delta_ac G_vb; evaluated in the principal frame without
// forming dP/dF (README §6). Vertex-major (x0, y0, z0, x1, ...) ordering.
Matrix12d ElementHessianFromPrincipal(const SignedSvd3& svd, const PrincipalHessian& h,
                                      const Eigen::Matrix<double, 4, 3>& shape_gradients,
                                      double volume);

}  // namespace ergo
