#include "ergo/equilibrium/ceres_equilibrium.h"

#include <chrono>
#include <cmath>

#include <ceres/gradient_problem.h>
#include <glog/logging.h>

#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/skew_matrix.h"

namespace ergo {
Eigen::Matrix3d LeftJacobianSO3(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  const Eigen::Matrix3d k = Skew(theta);
  if (angle < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * k + k * k / 6.0;
  const double a2 = angle * angle;
  return Eigen::Matrix3d::Identity() + (1 - std::cos(angle)) / a2 * k +
         (angle - std::sin(angle)) / (a2 * angle) * k * k;
}

EquilibriumFunction::EquilibriumFunction(const TotalPotential& potential, const Support& support,
                                         BodyState base)
    : potential_(potential), support_(support), base_(std::move(base)) {}

BodyState EquilibriumFunction::StateAt(const double* parameters) const {
  const ReducedLayout& layout = potential_.system().layout();
  const Eigen::Map<const Eigen::VectorXd> x(parameters, layout.size());
  BodyState state = base_;
  state.free_displacement += x.head(layout.core_offset());
  Eigen::Vector3d theta = Eigen::Vector3d::Zero();
  for (int j = 0; j < layout.core_count(); ++j) {
    const int component = layout.core_components()[j];
    (component < 3 ? state.centre[component] : theta[component - 3]) += x[layout.core_offset() + j];
  }
  state.rotation = RotationExp(theta) * base_.rotation;
  state.torque_angle = base_.torque_angle + theta;
  if (layout.support_size() > 0) {
    if (state.support_displacement.size() == 0)
      state.support_displacement = Eigen::VectorXd::Zero(layout.support_size());
    state.support_displacement += x.tail(layout.support_size());
  }
  return state;
}

bool EquilibriumFunction::Evaluate(const double* parameters, double* cost, double* gradient) const {
  const BodyState state = StateAt(parameters);
  if (!gradient) {
    *cost = potential_.Energy(state, support_);
    return std::isfinite(*cost);
  }
  TotalPotential::Evaluation e;
  potential_.Evaluate(state, support_, HessianKind::kExact, false, nullptr, &e);
  *cost = e.energy;
  const ReducedLayout& layout = potential_.system().layout();
  Eigen::Map<Eigen::VectorXd> g(gradient, layout.size());
  g = e.gradient;
  // Rotation: the world-frame gradient (without the torque's work term, which is linear in
  // θ here) mapped through J_l(θ)ᵀ.
  Eigen::Vector3d theta = Eigen::Vector3d::Zero(), world = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& torque = potential_.body().options().external_torque;
  std::vector<int> rotation_slots;
  for (int j = 0; j < layout.core_count(); ++j) {
    const int component = layout.core_components()[j];
    if (component < 3) continue;
    theta[component - 3] = parameters[layout.core_offset() + j];
    world[component - 3] = e.gradient[layout.core_offset() + j] + torque[component - 3];
    rotation_slots.push_back(j);
  }
  if (!rotation_slots.empty()) {
    const Eigen::Vector3d mapped = LeftJacobianSO3(theta).transpose() * world;
    for (int j : rotation_slots) {
      const int axis = layout.core_components()[j] - 3;
      g[layout.core_offset() + j] = mapped[axis] - torque[axis];
    }
  }
  return std::isfinite(*cost) && g.allFinite();
}

EquilibriumResult SolveEquilibriumWithCeres(const TotalPotential& potential, const Support& support,
                                            const BodyState& start, double relative_tolerance,
                                            const ceres::GradientProblemSolver::Options& options) {
  const auto begin = std::chrono::steady_clock::now();
  auto* function = new EquilibriumFunction(potential, support, start);
  ceres::GradientProblem problem(function);  // takes ownership
  Eigen::VectorXd x = Eigen::VectorXd::Zero(function->NumParameters());
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(options, problem, x.data(), &summary);

  EquilibriumResult result;
  result.state = function->StateAt(x.data());
  // Report the residual in the same (exp-map) coordinates as Newton.
  TotalPotential::Evaluation e;
  potential.Evaluate(result.state, support, HessianKind::kExact, false, nullptr, &e);
  const double load = potential.body().TotalLoad().norm();
  result.iterations = static_cast<int>(summary.iterations.size());
  result.residual = potential.ResidualNorm(e.gradient);
  result.relative_residual = result.residual / (load > 0 ? load : 1.0);
  result.energy = e.energy;
  result.contact_vertices = e.contacts.skin_vertices_in_contact();
  result.contact_springs = e.contacts.springs();
  result.max_penetration = e.contacts.max_penetration;
  result.contact_force = e.contacts.TotalForceOnBody();
  result.converged = result.relative_residual <= relative_tolerance;
  result.status =
      result.converged ? EquilibriumStatus::kConverged : EquilibriumStatus::kIterationCap;
  result.message = "ceres: " + summary.message;
  result.total_seconds = SecondsSince(begin);
  return result;
}

}  // namespace ergo
