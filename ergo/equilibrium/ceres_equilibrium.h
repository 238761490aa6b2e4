// The static equilibrium as an unconstrained minimisation for ceres::GradientProblemSolver
// (L-BFGS): a cross-check of, and a comparison point for, the Newton solver. Parameters
// x = (u^F, c, θ) relative to a base state, with R(x) = exp([θ]×) R₀, so the rotation part
// of ∇f is J_l(θ)ᵀ times the world-frame torque gradient (J_l the left Jacobian of exp).
#pragma once

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem_solver.h>

#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/total_potential.h"

namespace ergo {

class EquilibriumFunction : public ceres::FirstOrderFunction {
 public:
  // Keeps references to `potential` and `support`.
  EquilibriumFunction(const TotalPotential& potential, const Support& support, BodyState base);

  bool Evaluate(const double* parameters, double* cost, double* gradient) const override;
  int NumParameters() const override { return static_cast<int>(potential_.system().size()); }

  // The body state at parameters x.
  BodyState StateAt(const double* parameters) const;

 private:
  const TotalPotential& potential_;
  const Support& support_;
  BodyState base_;
};

// The left Jacobian of exp on SO(3): exp([θ + δ]×) ≈ exp([J_l(θ) δ]×) exp([θ]×).
Eigen::Matrix3d LeftJacobianSO3(const Eigen::Vector3d& theta);

// Minimises the total potential from `start` with Ceres (L-BFGS by default) and reports the
// result like the Newton solver (iterations = Ceres iterations; the time split is only the
// total). The convergence test on the force residual is evaluated at the end.
EquilibriumResult SolveEquilibriumWithCeres(const TotalPotential& potential, const Support& support,
                                            const BodyState& start, double relative_tolerance,
                                            const ceres::GradientProblemSolver::Options& options);

}  // namespace ergo
