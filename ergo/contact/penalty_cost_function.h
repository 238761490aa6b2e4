// The sliding-anchor penalty spring (paper Eq. 10, Appendix A) as a Ceres cost function:
// residual r = √k (p − π) with hand-written Jacobians over p and the feature's support
// vertices, exact inside the feature's Voronoi region. Ceres minimises ½‖r‖² = E/2, so a
// caller who wants E itself in a ceres::Problem passes 2k. Units: k in N/m, positions in m.
//
// Parameter blocks (each 3 doubles): p, then the feature's vertices in Feature::vertices
// order — (p, v) for a vertex, (p, e0, e1) for an edge, (p, t0, t1, t2) for a face. The
// region is fixed when the cost function is made: re-query the support (Support::ClosestPoint)
// and rebuild the cost when the anchor may have left its region.
#pragma once

#include <memory>

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "ergo/contact/feature.h"
#include "ergo/contact/point_feature_energy.h"

namespace ergo {

// r = √k (p − π) with π the anchor of `type`'s formula; if `jacobian` is not null, fills
// its leading 3 × 3(n+1) block with ∂r/∂(p, x0, …, x_{n−1}). Returns false (and leaves r
// unspecified) on a degenerate feature: an edge of zero length or a face of zero area.
bool SlidingAnchorResidual(FeatureType type, const Eigen::Vector3d& p, const FeaturePositions& x,
                           double k, Eigen::Vector3d* residual,
                           Eigen::Matrix<double, 3, 12>* jacobian);

// Vertex region: r = √k (p − v); blocks (p, v).
class VertexAnchorCostFunction : public ceres::SizedCostFunction<3, 3, 3> {
 public:
  explicit VertexAnchorCostFunction(double k);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double k_;
};

// Edge region: r = √k (d − t e), d = p − e0, e = e1 − e0, t = d·e/‖e‖²; blocks (p, e0, e1).
class EdgeAnchorCostFunction : public ceres::SizedCostFunction<3, 3, 3, 3> {
 public:
  explicit EdgeAnchorCostFunction(double k);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double k_;
};

// Face region: r = √k g N / h, N = e1 × e2, g = N·d, h = ‖N‖²; blocks (p, t0, t1, t2).
class FaceAnchorCostFunction : public ceres::SizedCostFunction<3, 3, 3, 3, 3> {
 public:
  explicit FaceAnchorCostFunction(double k);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double k_;
};

// The cost function for a feature type with stiffness k > 0 (CHECKed); the caller owns it
// (or hands it to a ceres::Problem, which takes ownership by default).
std::unique_ptr<ceres::CostFunction> MakeSlidingAnchorCostFunction(FeatureType type, double k);

}  // namespace ergo
