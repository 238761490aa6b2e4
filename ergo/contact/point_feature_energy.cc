#include "ergo/contact/point_feature_energy.h"

#include <glog/logging.h>
#include <Eigen/Geometry>

#include "ergo/mesh/skew_matrix.h"

namespace ergo {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// q(a, b) = ‖a × b‖² = ‖a‖²‖b‖² − (a·b)² (Lagrange), a quartic polynomial, with its
// gradient over (a, b) written as cross products (no cancellation) and its Hessian.
void CrossNormSquared(const Vector3d& a, const Vector3d& b, double* value, Vector6d* gradient,
                      Matrix6d* hessian) {
  const Vector3d c = a.cross(b);
  *value = c.squaredNorm();
  gradient->head<3>() = 2 * b.cross(c);  // 2(‖b‖² a − (a·b) b)
  gradient->tail<3>() = 2 * c.cross(a);  // 2(‖a‖² b − (a·b) a)
  if (hessian == nullptr) return;
  const Matrix3d identity = Matrix3d::Identity();
  const double ab = a.dot(b);
  hessian->topLeftCorner<3, 3>() = 2 * b.squaredNorm() * identity - 2 * b * b.transpose();
  hessian->bottomRightCorner<3, 3>() = 2 * a.squaredNorm() * identity - 2 * a * a.transpose();
  hessian->topRightCorner<3, 3>() =
      4 * a * b.transpose() - 2 * b * a.transpose() - 2 * ab * identity;
  hessian->bottomLeftCorner<3, 3>() = hessian->topRightCorner<3, 3>().transpose();
}

// f = num/den with ∇f = (∇num − f ∇den)/den and, differentiating f·den = num twice,
// Hf = (Hnum − ∇f ∇denᵀ − ∇den ∇fᵀ − f Hden)/den. Hessians are skipped if `hessian` is null.
template <int N>
void Quotient(double num, const Eigen::Matrix<double, N, 1>& num_gradient,
              const Eigen::Matrix<double, N, N>* num_hessian, double den,
              const Eigen::Matrix<double, N, 1>& den_gradient,
              const Eigen::Matrix<double, N, N>* den_hessian, double* value,
              Eigen::Matrix<double, N, 1>* gradient, Eigen::Matrix<double, N, N>* hessian) {
  *value = num / den;
  *gradient = (num_gradient - *value * den_gradient) / den;
  if (hessian == nullptr) return;
  const Eigen::Matrix<double, N, N> outer = *gradient * den_gradient.transpose();
  *hessian = (*num_hessian - outer - outer.transpose() - *value * *den_hessian) / den;
}

// The local variables (d, e_1, …, e_m) = (p − x0, x1 − x0, …, xm − x0) as a linear map
// from the vertex coordinates (p, x0, x1, …, xm): 3(m+1) × 3(m+2).
template <int M>
Eigen::Matrix<double, 3 * (M + 1), 3 * (M + 2)> LocalFromVertexCoordinates() {
  Eigen::Matrix<double, 3 * (M + 1), 3 * (M + 2)> a;
  a.setZero();
  const Matrix3d identity = Matrix3d::Identity();
  a.template block<3, 3>(0, 0) = identity;  // d = p − x0
  for (int row = 0; row <= M; ++row) a.template block<3, 3>(3 * row, 3) = -identity;
  for (int i = 1; i <= M; ++i) a.template block<3, 3>(3 * i, 3 * (i + 1)) = identity;
  return a;
}

// Edge energy over (d, e): k ‖d × e‖² / ‖e‖².
void EdgeLocal(const Vector3d& d, const Vector3d& e, double k, double* value, Vector6d* gradient,
               Matrix6d* hessian) {
  double num;
  Vector6d num_gradient;
  Matrix6d num_hessian;
  CrossNormSquared(d, e, &num, &num_gradient, hessian ? &num_hessian : nullptr);
  const double den = e.squaredNorm();
  CHECK_GT(den, 0.0) << "edge of zero length";
  Vector6d den_gradient;
  den_gradient << Vector3d::Zero(), 2 * e;
  Matrix6d den_hessian = Matrix6d::Zero();
  den_hessian.bottomRightCorner<3, 3>() = 2 * Matrix3d::Identity();
  Quotient<6>(num, num_gradient, &num_hessian, den, den_gradient, &den_hessian, value, gradient,
              hessian);
  *value *= k;
  *gradient *= k;
  if (hessian) *hessian *= k;
}

// Face energy over (d, e1, e2): k g²/h with g = d·(e1 × e2), h = ‖e1 × e2‖².
void FaceLocal(const Vector3d& d, const Vector3d& e1, const Vector3d& e2, double k, double* value,
               Vector9d* gradient, Matrix9d* hessian) {
  const Vector3d normal = e1.cross(e2);
  const double g = d.dot(normal);
  Vector9d g_gradient;  // the triple product's partials are cross products
  g_gradient << normal, e2.cross(d), d.cross(e1);

  double h;
  Vector6d h_gradient6;
  Matrix6d h_hessian6;
  CrossNormSquared(e1, e2, &h, &h_gradient6, hessian ? &h_hessian6 : nullptr);
  CHECK_GT(h, 0.0) << "triangle of zero area";
  Vector9d h_gradient;
  h_gradient << Vector3d::Zero(), h_gradient6;

  Matrix9d u_hessian, h_hessian;
  if (hessian) {
    // Hessian of the trilinear g: zero diagonal blocks, ∂²g/∂d∂e1 = −[e2]×,
    // ∂²g/∂d∂e2 = [e1]×, ∂²g/∂e1∂e2 = −[d]×, and their transposes.
    Matrix9d g_hessian = Matrix9d::Zero();
    g_hessian.block<3, 3>(0, 3) = -Skew(e2);
    g_hessian.block<3, 3>(0, 6) = Skew(e1);
    g_hessian.block<3, 3>(3, 6) = -Skew(d);
    g_hessian.block<3, 3>(3, 0) = g_hessian.block<3, 3>(0, 3).transpose();
    g_hessian.block<3, 3>(6, 0) = g_hessian.block<3, 3>(0, 6).transpose();
    g_hessian.block<3, 3>(6, 3) = g_hessian.block<3, 3>(3, 6).transpose();
    u_hessian = 2 * g_gradient * g_gradient.transpose() + 2 * g * g_hessian;  // of u = g²
    h_hessian.setZero();
    h_hessian.bottomRightCorner<6, 6>() = h_hessian6;
  }
  Quotient<9>(g * g, 2 * g * g_gradient, &u_hessian, h, h_gradient, &h_hessian, value, gradient,
              hessian);
  *value *= k;
  *gradient *= k;
  if (hessian) *hessian *= k;
}

}  // namespace

// ---- Vertex ----

double PointVertexEnergy(const Vector3d& p, const Vector3d& v, double k) {
  return k * (p - v).squaredNorm();
}

Vector6d PointVertexEnergyGradient(const Vector3d& p, const Vector3d& v, double k) {
  const Vector3d r = 2 * k * (p - v);
  Vector6d gradient;
  gradient << r, -r;
  return gradient;
}

Matrix6d PointVertexEnergyHessian(const Vector3d& /*p*/, const Vector3d& /*v*/, double k) {
  const Matrix3d block = 2 * k * Matrix3d::Identity();
  Matrix6d hessian;
  hessian << block, -block, -block, block;
  return hessian;
}

// ---- Edge ----

double PointEdgeEnergy(const Vector3d& p, const Vector3d& e0, const Vector3d& e1, double k) {
  const Vector3d e = e1 - e0;
  const double den = e.squaredNorm();
  CHECK_GT(den, 0.0) << "edge of zero length";
  return k * (p - e0).cross(e).squaredNorm() / den;
}

Vector9d PointEdgeEnergyGradient(const Vector3d& p, const Vector3d& e0, const Vector3d& e1,
                                 double k) {
  double value;
  Vector6d local;
  EdgeLocal(p - e0, e1 - e0, k, &value, &local, nullptr);
  static const Eigen::Matrix<double, 6, 9> a = LocalFromVertexCoordinates<1>();
  return a.transpose() * local;
}

Matrix9d PointEdgeEnergyHessian(const Vector3d& p, const Vector3d& e0, const Vector3d& e1,
                                double k) {
  double value;
  Vector6d gradient;
  Matrix6d local;
  EdgeLocal(p - e0, e1 - e0, k, &value, &gradient, &local);
  static const Eigen::Matrix<double, 6, 9> a = LocalFromVertexCoordinates<1>();
  return a.transpose() * local * a;
}

// ---- Face ----

double PointFaceEnergy(const Vector3d& p, const Vector3d& t0, const Vector3d& t1,
                       const Vector3d& t2, double k) {
  const Vector3d normal = (t1 - t0).cross(t2 - t0);
  const double h = normal.squaredNorm();
  CHECK_GT(h, 0.0) << "triangle of zero area";
  const double g = normal.dot(p - t0);
  return k * g * g / h;
}

Vector12d PointFaceEnergyGradient(const Vector3d& p, const Vector3d& t0, const Vector3d& t1,
                                  const Vector3d& t2, double k) {
  double value;
  Vector9d local;
  FaceLocal(p - t0, t1 - t0, t2 - t0, k, &value, &local, nullptr);
  static const Eigen::Matrix<double, 9, 12> a = LocalFromVertexCoordinates<2>();
  return a.transpose() * local;
}

Matrix12d PointFaceEnergyHessian(const Vector3d& p, const Vector3d& t0, const Vector3d& t1,
                                 const Vector3d& t2, double k) {
  double value;
  Vector9d gradient;
  Matrix9d local;
  FaceLocal(p - t0, t1 - t0, t2 - t0, k, &value, &gradient, &local);
  static const Eigen::Matrix<double, 9, 12> a = LocalFromVertexCoordinates<2>();
  return a.transpose() * local * a;
}

// ---- Any region ----

Vector3d SlidingAnchor(FeatureType type, const Vector3d& p, const FeaturePositions& x) {
  switch (type) {
    case FeatureType::kVertex:
      return x[0];
    case FeatureType::kEdge: {
      const Vector3d e = x[1] - x[0];
      const double den = e.squaredNorm();
      CHECK_GT(den, 0.0) << "edge of zero length";
      return x[0] + ((p - x[0]).dot(e) / den) * e;
    }
    case FeatureType::kFace: {
      const Vector3d normal = (x[1] - x[0]).cross(x[2] - x[0]);
      const double h = normal.squaredNorm();
      CHECK_GT(h, 0.0) << "triangle of zero area";
      return p - (normal.dot(p - x[0]) / h) * normal;
    }
  }
  LOG(FATAL) << "unknown feature type";
  return p;
}

SlidingAnchorEnergy EvaluateSlidingAnchor(FeatureType type, const Vector3d& p,
                                          const FeaturePositions& x, double k, bool with_hessian) {
  SlidingAnchorEnergy result;
  result.size = 3 * (FeatureVertexCount(type) + 1);
  switch (type) {
    case FeatureType::kVertex:
      result.energy = PointVertexEnergy(p, x[0], k);
      result.gradient.head<6>() = PointVertexEnergyGradient(p, x[0], k);
      if (with_hessian) result.hessian.topLeftCorner<6, 6>() = PointVertexEnergyHessian(p, x[0], k);
      break;
    case FeatureType::kEdge: {
      Vector6d gradient;
      Matrix6d hessian;
      EdgeLocal(p - x[0], x[1] - x[0], k, &result.energy, &gradient,
                with_hessian ? &hessian : nullptr);
      static const Eigen::Matrix<double, 6, 9> a = LocalFromVertexCoordinates<1>();
      result.gradient.head<9>() = a.transpose() * gradient;
      if (with_hessian) result.hessian.topLeftCorner<9, 9>() = a.transpose() * hessian * a;
      break;
    }
    case FeatureType::kFace: {
      Vector9d gradient;
      Matrix9d hessian;
      FaceLocal(p - x[0], x[1] - x[0], x[2] - x[0], k, &result.energy, &gradient,
                with_hessian ? &hessian : nullptr);
      static const Eigen::Matrix<double, 9, 12> a = LocalFromVertexCoordinates<2>();
      result.gradient = a.transpose() * gradient;
      if (with_hessian) result.hessian = a.transpose() * hessian * a;
      break;
    }
  }
  return result;
}

}  // namespace ergo
