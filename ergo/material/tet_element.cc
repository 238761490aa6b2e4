#include "ergo/material/tet_element.h"

#include <glog/logging.h>
#include <Eigen/Geometry>
#include <Eigen/LU>

namespace ergo {

double SignedTetVolume(const TetPositions& x) {
  const Eigen::Vector3d e1 = x.col(1) - x.col(0);
  const Eigen::Vector3d e2 = x.col(2) - x.col(0);
  const Eigen::Vector3d e3 = x.col(3) - x.col(0);
  return e1.dot(e2.cross(e3)) / 6.0;
}

std::optional<TetRestData> ComputeTetRestData(const TetPositions& rest, double min_volume) {
  CHECK_GE(min_volume, 0.0);
  const double volume = SignedTetVolume(rest);
  if (!(volume > min_volume)) return std::nullopt;  // also refuses NaN
  Eigen::Matrix3d dm;
  dm << rest.col(1) - rest.col(0), rest.col(2) - rest.col(0), rest.col(3) - rest.col(0);
  TetRestData data;
  data.dm_inverse = dm.inverse();
  data.volume = volume;
  return data;
}

Eigen::Matrix3d DeformationGradient(const TetRestData& rest, const TetPositions& x) {
  Eigen::Matrix3d ds;
  ds << x.col(1) - x.col(0), x.col(2) - x.col(0), x.col(3) - x.col(0);
  return ds * rest.dm_inverse;
}

// With G the 4x3 matrix whose rows 1..3 are Dm^-1 and row 0 minus their sum,
// F = sum_v x_v G_v^T, so dF_ab/dx_vc = delta_ac G_vb.

Vector12d ElementGradientFromStress(const TetRestData& rest, const Eigen::Matrix3d& p) {
  // dE/dx_vc = V sum_b P_cb G_vb: the 3x4 matrix V P G^T, stored vertex-major.
  Vector12d gradient;
  Eigen::Map<TetPositions> g(gradient.data());
  g.rightCols<3>().noalias() = rest.volume * p * rest.dm_inverse.transpose();
  g.col(0) = -g.rightCols<3>().rowwise().sum();
  return gradient;
}

Matrix12d ElementHessianFromStressDerivative(const TetRestData& rest,
                                             const Matrix9d& stress_derivative) {
  // d2E/dx_vc dx_wd = V sum_bf G_vb G_wf H9(c + 3b, d + 3f): for each coordinate pair
  // (c, d) the 3x3 slice S_bf = H9(c + 3b, d + 3f) is mapped to the 4x4 vertex block
  // V G S G^T = [[sum W, -colsum W], [-rowsum W, W]] with W = V Dm^-1 S Dm^-T:
  // 6 small products (the (d, c) slices are transposes) instead of a dense 12x9x9x12 one.
  //
  // PSD: for any y in R^12, y^T H12 y = V (D y)^T H9 (D y) >= 0 when H9 is PSD,
  // with D = d vec(F) / dx (9x12) and V > 0; so D^T (PSD) D is PSD.
  Matrix12d hessian;
  const Eigen::Matrix3d& a = rest.dm_inverse;
  for (int c = 0; c < 3; ++c) {
    for (int d = c; d < 3; ++d) {
      const Eigen::Map<const Eigen::Matrix3d, 0, Eigen::Stride<27, 3>> slice(
          stress_derivative.data() + c + 9 * d);
      Eigen::Matrix3d w;
      w.noalias() = rest.volume * (a * slice * a.transpose());
      const Eigen::RowVector3d column_sums = w.colwise().sum();
      const Eigen::Vector3d row_sums = w.rowwise().sum();
      Eigen::Matrix4d block;
      block(0, 0) = row_sums.sum();
      block.block<1, 3>(0, 1) = -column_sums;
      block.block<3, 1>(1, 0) = -row_sums;
      block.block<3, 3>(1, 1) = w;
      for (int v = 0; v < 4; ++v) {
        for (int u = 0; u < 4; ++u) {
          hessian(3 * v + c, 3 * u + d) = block(v, u);
          hessian(3 * u + d, 3 * v + c) = block(v, u);
        }
      }
    }
  }
  return hessian;
}

Eigen::Matrix<double, 4, 3> ShapeGradients(const TetRestData& rest) {
  Eigen::Matrix<double, 4, 3> g;
  g.bottomRows<3>() = rest.dm_inverse;
  g.row(0) = -rest.dm_inverse.colwise().sum();
  return g;
}

void EvaluateElement(const NeoHookean& material, const TetRestData& rest, const TetPositions& x,
                     HessianKind kind, double* energy, Vector12d* gradient, Matrix12d* hessian) {
  const Eigen::Matrix3d f = DeformationGradient(rest, x);
  double psi = 0;
  Eigen::Matrix3d p;
  SignedSvd3 svd;
  PrincipalHessian h;
  const bool want_hessian = hessian != nullptr;
  material.EvaluatePrincipalFrame(f, kind, energy != nullptr ? &psi : nullptr,
                                  gradient != nullptr ? &p : nullptr, want_hessian ? &svd : nullptr,
                                  want_hessian ? &h : nullptr);
  if (energy != nullptr) *energy = rest.volume * psi;
  if (gradient != nullptr) *gradient = ElementGradientFromStress(rest, p);
  if (want_hessian)
    *hessian = ElementHessianFromPrincipal(svd, h, ShapeGradients(rest), rest.volume);
}

double ElementEnergy(const NeoHookean& material, const TetRestData& rest, const TetPositions& x) {
  double energy = 0;
  EvaluateElement(material, rest, x, HessianKind::kExact, &energy, nullptr, nullptr);
  return energy;
}

Vector12d ElementGradient(const NeoHookean& material, const TetRestData& rest,
                          const TetPositions& x) {
  Vector12d gradient;
  EvaluateElement(material, rest, x, HessianKind::kExact, nullptr, &gradient, nullptr);
  return gradient;
}

Matrix12d ElementHessian(const NeoHookean& material, const TetRestData& rest, const TetPositions& x,
                         HessianKind kind) {
  Matrix12d hessian;
  EvaluateElement(material, rest, x, kind, nullptr, nullptr, &hessian);
  return hessian;
}

}  // namespace ergo
