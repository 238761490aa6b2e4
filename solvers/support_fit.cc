#include "solvers/support_fit.h"

#include <cmath>
#include <set>

#include <ceres/ceres.h>
#include <glog/logging.h>

namespace ergo {

TargetResidual::TargetResidual(double weight, double target)
    : sqrt_weight_(std::sqrt(weight)), target_(target) {
  set_num_residuals(1);
  mutable_parameter_block_sizes()->push_back(1);
}

bool TargetResidual::Evaluate(double const* const* parameters, double* residuals,
                              double** jacobians) const {
  residuals[0] = sqrt_weight_ * (parameters[0][0] - target_);
  if (jacobians && jacobians[0]) jacobians[0][0] = sqrt_weight_;
  return true;
}

UmbrellaResidual::UmbrellaResidual(double lambda, int designed_neighbours, int all_neighbours)
    : sqrt_lambda_(std::sqrt(lambda)), designed_(designed_neighbours), all_(all_neighbours) {
  CHECK_GT(all_neighbours, 0);
  CHECK_LE(designed_neighbours, all_neighbours);
  set_num_residuals(1);
  for (int k = 0; k <= designed_neighbours; ++k) mutable_parameter_block_sizes()->push_back(1);
}

bool UmbrellaResidual::Evaluate(double const* const* parameters, double* residuals,
                                double** jacobians) const {
  const double share = 1.0 / all_;
  double value = parameters[0][0];
  for (int k = 1; k <= designed_; ++k) value -= share * parameters[k][0];
  residuals[0] = sqrt_lambda_ * value;
  if (jacobians) {
    if (jacobians[0]) jacobians[0][0] = sqrt_lambda_;
    for (int k = 1; k <= designed_; ++k)
      if (jacobians[k]) jacobians[k][0] = -sqrt_lambda_ * share;
  }
  return true;
}

SupportFit FitSupport(const TriMesh& support, const Eigen::VectorXi& active,
                      const Eigen::VectorXd& target, const Eigen::VectorXd& weight,
                      const Eigen::Vector3d& up, const SupportFitOptions& options) {
  const Eigen::Index n = support.vertices.rows();
  CHECK_EQ(target.size(), n);
  CHECK_EQ(weight.size(), n);
  std::vector<std::set<int>> neighbours(static_cast<size_t>(n));
  for (Eigen::Index f = 0; f < support.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = support.triangles(f, k), b = support.triangles(f, (k + 1) % 3);
      neighbours[a].insert(b);
      neighbours[b].insert(a);
    }
  }
  std::vector<bool> designed(static_cast<size_t>(n), false);
  for (Eigen::Index i = 0; i < active.size(); ++i) designed[active[i]] = true;

  SupportFit fit;
  fit.displacement = Eigen::VectorXd::Zero(n);
  fit.target = target;
  fit.weight = weight;
  double weight_sum = 0;
  int targets = 0;
  for (Eigen::Index i = 0; i < active.size(); ++i) {
    if (weight[active[i]] > 0) {
      weight_sum += weight[active[i]];
      ++targets;
    }
  }
  fit.positions = support.vertices;
  if (targets == 0) {
    fit.report = "no designed vertex has a target: the support is left as it is";
    return fit;
  }
  const double lambda = options.smoothness * weight_sum / targets;

  ceres::Problem::Options problem_options;
  ceres::Problem problem(problem_options);
  double* d = fit.displacement.data();
  for (Eigen::Index i = 0; i < active.size(); ++i) {
    const int v = active[i];
    problem.AddParameterBlock(d + v, 1);
    if (weight[v] > 0)
      problem.AddResidualBlock(new TargetResidual(weight[v], target[v]), nullptr, d + v);
  }
  for (Eigen::Index i = 0; i < active.size(); ++i) {
    const int v = active[i];
    if (neighbours[v].empty()) continue;
    std::vector<double*> blocks = {d + v};
    for (int j : neighbours[v])
      if (designed[j]) blocks.push_back(d + j);
    problem.AddResidualBlock(new UmbrellaResidual(lambda, static_cast<int>(blocks.size()) - 1,
                                                  static_cast<int>(neighbours[v].size())),
                             nullptr, blocks);
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = 10;  // linear: one step solves it
  solver_options.function_tolerance = 1e-14;
  solver_options.gradient_tolerance = 1e-16;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  fit.report = summary.BriefReport();

  double misfit = 0;
  for (Eigen::Index i = 0; i < active.size(); ++i) {
    const int v = active[i];
    if (weight[v] > 0) misfit += weight[v] * std::pow(fit.displacement[v] - target[v], 2);
    fit.positions.row(v) += fit.displacement[v] * up.transpose();
  }
  fit.rms_misfit = std::sqrt(misfit / weight_sum);
  return fit;
}

}  // namespace ergo
