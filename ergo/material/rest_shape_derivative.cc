#include "ergo/material/rest_shape_derivative.h"

#include <glog/logging.h>

namespace ergo {
namespace {

// dDm for a unit change of rest coordinate (corner v, axis c): Dm's columns are X_k − X_0.
Eigen::Matrix3d RestEdgeChange(int v, int c) {
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (v == 0) {
    d.row(c).setConstant(-1.0);
  } else {
    d(c, v - 1) = 1.0;
  }
  return d;
}

TetRestData RestDataOf(const TetPositions& rest) {
  const auto data = ComputeTetRestData(rest);
  CHECK(data) << "rest tet with non-positive volume";
  return *data;
}

}  // namespace

Vector12d TetVolumeRestGradient(const TetPositions& rest) {
  const TetRestData data = RestDataOf(rest);
  Vector12d gradient;
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c)
      gradient[3 * v + c] = data.volume * (data.dm_inverse * RestEdgeChange(v, c)).trace();
  return gradient;
}

Vector12d ElementEnergyRestGradient(const NeoHookean& material, const TetPositions& rest,
                                    const TetPositions& x) {
  const TetRestData data = RestDataOf(rest);
  const Eigen::Matrix3d f = DeformationGradient(data, x);
  double psi = 0;
  Eigen::Matrix3d p;
  material.Evaluate(f, HessianKind::kExact, &psi, &p, nullptr);
  Vector12d gradient;
  for (int v = 0; v < 4; ++v) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::Matrix3d d_dm = RestEdgeChange(v, c);
      const double d_volume = data.volume * (data.dm_inverse * d_dm).trace();
      const Eigen::Matrix3d d_f = -f * d_dm * data.dm_inverse;
      gradient[3 * v + c] = d_volume * psi + data.volume * (p.array() * d_f.array()).sum();
    }
  }
  return gradient;
}

Matrix12d ElementForceRestJacobian(const NeoHookean& material, const TetPositions& rest,
                                   const TetPositions& x) {
  const TetRestData data = RestDataOf(rest);
  const Eigen::Matrix3d& w = data.dm_inverse;
  const Eigen::Matrix3d f = DeformationGradient(data, x);
  Eigen::Matrix3d p;
  Matrix9d dp_df;
  material.Evaluate(f, HessianKind::kExact, nullptr, &p, &dp_df);
  Matrix12d jacobian;
  for (int v = 0; v < 4; ++v) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::Matrix3d d_dm = RestEdgeChange(v, c);
      const double d_volume = data.volume * (w * d_dm).trace();
      const Eigen::Matrix3d d_w = -w * d_dm * w;
      const Eigen::Matrix3d d_f = f * d_dm * -w;
      Eigen::Matrix3d d_p;
      Eigen::Map<Eigen::Matrix<double, 9, 1>>(d_p.data()) =
          dp_df * Eigen::Map<const Eigen::Matrix<double, 9, 1>>(d_f.data());
      // The forces on corners 1..3 are the columns of V P Wᵀ; corner 0 takes minus their sum.
      Eigen::Matrix3d d_forces =
          d_volume * p * w.transpose() + data.volume * (d_p * w.transpose() + p * d_w.transpose());
      Eigen::Map<TetPositions> column(jacobian.col(3 * v + c).data());
      column.rightCols<3>() = d_forces;
      column.col(0) = -d_forces.rowwise().sum();
    }
  }
  return jacobian;
}

}  // namespace ergo
