// The least-squares fit shared by the geometric baselines (Sit & Relax, Leimer et al. 2016;
// Pose to Seat, Leimer et al. 2020; solvers/README.md "Baselines"): each designed support
// vertex v moves by d_v along the load line (d > 0 towards the body) to a target height
// with weight w_v ≥ 0, against an umbrella-Laplacian smoothness term on the designed patch:
//
//   min_d  Σ_v w_v (d_v − d*_v)²  +  λ Σ_v (d_v − mean of d over v's neighbours)²
//
// with the patch's rim (non-designed neighbours) held at d = 0. A ceres::Problem with one
// residual block per term and analytic Jacobians (the residuals are linear in d; the
// GradientChecker tests check them), solved by Ceres' sparse normal Cholesky.
#pragma once

#include <string>
#include <vector>

#include <ceres/cost_function.h>
#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// √w (d − d*): one residual, one parameter d (size 1).
class TargetResidual : public ceres::CostFunction {
 public:
  TargetResidual(double weight, double target);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double sqrt_weight_, target_;
};

// √λ (d_v − (1/k) Σ_j d_j) over v's k neighbours, of which the designed ones are parameters
// (block 0 is d_v, then one block per designed neighbour) and the others are held at 0.
class UmbrellaResidual : public ceres::CostFunction {
 public:
  UmbrellaResidual(double lambda, int designed_neighbours, int all_neighbours);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double sqrt_lambda_;
  int designed_, all_;
};

struct SupportFitOptions {
  // λ relative to the mean weight of the vertices with a target: 1 gives the smoothness as
  // much say as an average target.
  double smoothness = 1.0;
};

struct SupportFit {
  Eigen::VectorXd displacement;    // d per support vertex (0 off the designed patch), m
  Eigen::VectorXd target, weight;  // d* and w as given
  Vertices positions;              // the fitted support's vertices
  double rms_misfit = 0;           // √(Σ w (d − d*)² / Σ w), m
  std::string report;              // Ceres' brief report
};

// `active` lists the designed support vertices; `target` and `weight` have one entry per
// support vertex (read at active ones; weight 0 = no target). `up` is the unit vector
// towards the body (minus the load direction).
SupportFit FitSupport(const TriMesh& support, const Eigen::VectorXi& active,
                      const Eigen::VectorXd& target, const Eigen::VectorXd& weight,
                      const Eigen::Vector3d& up, const SupportFitOptions& options);

}  // namespace ergo
