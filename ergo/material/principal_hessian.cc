#include "ergo/material/principal_hessian.h"

namespace ergo {
namespace {

constexpr int kHessianPairFirst[3] = {0, 0, 1};
constexpr int kHessianPairSecond[3] = {1, 2, 2};

// Assembles the (3N)x(3N) Hessian of psi(F) with F = sum_v x_v g_v^T (N "vertices",
// g_v the rows of g), scaled by `scale`. With g_hat = g V the map is diagonal in the
// principal frame, and each 3x3 block (v, w) is U M_vw U^T with (README eq. 12)
//   M_vw(c, c) = sum_b alpha_cb g_hat_vb g_hat_wb,  alpha_cc = K_cc, alpha_cb = A_cb,
//   M_vw(c, d) = K_cd g_hat_vc g_hat_wd + B_cd g_hat_vd g_hat_wc   (c != d),
// K the stretch block and A, B the pair blocks. ~75 flops per block instead of a dense
// (V (x) U) K (V (x) U)^T product.
template <int N>
Eigen::Matrix<double, 3 * N, 3 * N> AssembleInPrincipalFrame(const SignedSvd3& svd,
                                                             const PrincipalHessian& h,
                                                             const Eigen::Matrix<double, N, 3>& g,
                                                             double scale) {
  Eigen::Matrix3d alpha;  // alpha(c, b)
  Eigen::Matrix3d flip;   // B(c, d), symmetric, zero diagonal
  alpha.diagonal() = h.stretch_block.diagonal();
  flip.diagonal().setZero();
  for (int p = 0; p < 3; ++p) {
    const int i = kHessianPairFirst[p];
    const int j = kHessianPairSecond[p];
    alpha(i, j) = alpha(j, i) = 0.5 * (h.difference_quotient(p) + h.sum_quotient(p));
    flip(i, j) = flip(j, i) = 0.5 * (h.difference_quotient(p) - h.sum_quotient(p));
  }
  const Eigen::Matrix<double, N, 3> g_hat = g * svd.v;
  const Eigen::Matrix3d scaled_u = scale * svd.u;
  Eigen::Matrix<double, 3 * N, 3 * N> out;
  for (int v = 0; v < N; ++v) {
    for (int w = v; w < N; ++w) {
      const Eigen::Vector3d products = g_hat.row(v).cwiseProduct(g_hat.row(w)).transpose();
      Eigen::Matrix3d m;
      m.diagonal().noalias() = alpha * products;
      for (int p = 0; p < 3; ++p) {
        const int c = kHessianPairFirst[p];
        const int d = kHessianPairSecond[p];
        const double k = h.stretch_block(c, d);
        const double b = flip(c, d);
        m(c, d) = k * g_hat(v, c) * g_hat(w, d) + b * g_hat(v, d) * g_hat(w, c);
        m(d, c) = k * g_hat(v, d) * g_hat(w, c) + b * g_hat(v, c) * g_hat(w, d);
      }
      Eigen::Matrix3d block;
      block.noalias() = scaled_u * m * svd.u.transpose();
      out.template block<3, 3>(3 * v, 3 * w) = block;
      if (w != v) out.template block<3, 3>(3 * w, 3 * v) = block.transpose();
    }
  }
  return out;
}

}  // namespace

Matrix9d StressDerivativeFromPrincipal(const SignedSvd3& svd, const PrincipalHessian& h) {
  // F = sum_b F.col(b) e_b^T: three "vertices" with g = I.
  return AssembleInPrincipalFrame<3>(svd, h, Eigen::Matrix3d::Identity(), 1.0);
}

Matrix12d ElementHessianFromPrincipal(const SignedSvd3& svd, const PrincipalHessian& h,
                                      const Eigen::Matrix<double, 4, 3>& shape_gradients,
                                      double volume) {
  return AssembleInPrincipalFrame<4>(svd, h, shape_gradients, volume);
}

}  // namespace ergo
