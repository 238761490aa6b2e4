#include "ergo/contact/penalty_cost_function.h"

#include <cmath>

#include <glog/logging.h>
#include <Eigen/Geometry>

#include "ergo/mesh/skew_matrix.h"

namespace ergo {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using RowMajor3x3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// Shared Evaluate: n feature vertices, parameters (p, x0, …, x_{n−1}).
bool EvaluateBlocks(FeatureType type, double k, double const* const* parameters, double* residuals,
                    double** jacobians) {
  const int n = FeatureVertexCount(type);
  const Vector3d p = Eigen::Map<const Vector3d>(parameters[0]);
  FeaturePositions x;
  for (int i = 0; i < n; ++i) x[i] = Eigen::Map<const Vector3d>(parameters[i + 1]);
  Vector3d r;
  Eigen::Matrix<double, 3, 12> jacobian;
  if (!SlidingAnchorResidual(type, p, x, k, &r, jacobians ? &jacobian : nullptr)) return false;
  Eigen::Map<Vector3d> residual_out(residuals);
  residual_out = r;
  if (jacobians) {
    for (int block = 0; block <= n; ++block) {
      if (jacobians[block]) {
        Eigen::Map<RowMajor3x3> block_out(jacobians[block]);
        block_out = jacobian.block<3, 3>(0, 3 * block);
      }
    }
  }
  return true;
}

}  // namespace

bool SlidingAnchorResidual(FeatureType type, const Vector3d& p, const FeaturePositions& x, double k,
                           Vector3d* residual, Eigen::Matrix<double, 3, 12>* jacobian) {
  const double root_k = std::sqrt(k);
  if (jacobian) jacobian->setZero();
  switch (type) {
    case FeatureType::kVertex: {
      *residual = root_k * (p - x[0]);
      if (jacobian) {
        jacobian->block<3, 3>(0, 0) = root_k * Matrix3d::Identity();
        jacobian->block<3, 3>(0, 3) = -root_k * Matrix3d::Identity();
      }
      return true;
    }
    case FeatureType::kEdge: {
      const Vector3d d = p - x[0];
      const Vector3d e = x[1] - x[0];
      const double den = e.squaredNorm();
      if (!(den > 0)) return false;
      const double t = d.dot(e) / den;
      *residual = root_k * (d - t * e);
      if (jacobian) {
        // ∂r/∂d = √k (I − e eᵀ/‖e‖²); ∂r/∂e = −√k (t I + e ∂t/∂eᵀ), ∂t/∂e = (d − 2t e)/‖e‖².
        const Matrix3d r_d = root_k * (Matrix3d::Identity() - e * e.transpose() / den);
        const Matrix3d r_e =
            -root_k * (t * Matrix3d::Identity() + e * ((d - 2 * t * e) / den).transpose());
        jacobian->block<3, 3>(0, 0) = r_d;
        jacobian->block<3, 3>(0, 3) = -r_d - r_e;
        jacobian->block<3, 3>(0, 6) = r_e;
      }
      return true;
    }
    case FeatureType::kFace: {
      const Vector3d d = p - x[0];
      const Vector3d e1 = x[1] - x[0];
      const Vector3d e2 = x[2] - x[0];
      const Vector3d normal = e1.cross(e2);
      const double h = normal.squaredNorm();
      if (!(h > 0)) return false;
      const double g = normal.dot(d);
      const double c = g / h;  // r = √k c N
      *residual = root_k * c * normal;
      if (jacobian) {
        // ∂c/∂· = ∂g/∂·/h − g ∂h/∂·/h² with ∂g/∂e1 = e2 × d, ∂g/∂e2 = d × e1,
        // ∂h/∂e1 = 2 e2 × N, ∂h/∂e2 = 2 N × e1; ∂N/∂e1 = −[e2]×, ∂N/∂e2 = [e1]×.
        const Vector3d c_e1 = e2.cross(d) / h - (2 * g / (h * h)) * e2.cross(normal);
        const Vector3d c_e2 = d.cross(e1) / h - (2 * g / (h * h)) * normal.cross(e1);
        const Matrix3d r_d = root_k * normal * normal.transpose() / h;
        const Matrix3d r_e1 = root_k * (normal * c_e1.transpose() - c * Skew(e2));
        const Matrix3d r_e2 = root_k * (normal * c_e2.transpose() + c * Skew(e1));
        jacobian->block<3, 3>(0, 0) = r_d;
        jacobian->block<3, 3>(0, 3) = -(r_d + r_e1 + r_e2);
        jacobian->block<3, 3>(0, 6) = r_e1;
        jacobian->block<3, 3>(0, 9) = r_e2;
      }
      return true;
    }
  }
  LOG(FATAL) << "unknown feature type";
  return false;
}

VertexAnchorCostFunction::VertexAnchorCostFunction(double k) : k_(k) { CHECK_GT(k, 0.0); }
bool VertexAnchorCostFunction::Evaluate(double const* const* parameters, double* residuals,
                                        double** jacobians) const {
  return EvaluateBlocks(FeatureType::kVertex, k_, parameters, residuals, jacobians);
}

EdgeAnchorCostFunction::EdgeAnchorCostFunction(double k) : k_(k) { CHECK_GT(k, 0.0); }
bool EdgeAnchorCostFunction::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  return EvaluateBlocks(FeatureType::kEdge, k_, parameters, residuals, jacobians);
}

FaceAnchorCostFunction::FaceAnchorCostFunction(double k) : k_(k) { CHECK_GT(k, 0.0); }
bool FaceAnchorCostFunction::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  return EvaluateBlocks(FeatureType::kFace, k_, parameters, residuals, jacobians);
}

std::unique_ptr<ceres::CostFunction> MakeSlidingAnchorCostFunction(FeatureType type, double k) {
  switch (type) {
    case FeatureType::kVertex:
      return std::make_unique<VertexAnchorCostFunction>(k);
    case FeatureType::kEdge:
      return std::make_unique<EdgeAnchorCostFunction>(k);
    case FeatureType::kFace:
      return std::make_unique<FaceAnchorCostFunction>(k);
  }
  LOG(FATAL) << "unknown feature type";
  return nullptr;
}

}  // namespace ergo
