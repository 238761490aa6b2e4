// Smooth test functions with a known minimum, for checking the outer optimisers through the
// same Objective interface as a DesignProblem. Each coordinate is read as one vertex's
// travel in a unit of `metres_per_unit` (default 1 cm), so the paper's probe lengths
// (1 µm … 2 mm, §4.1), the millimetre scaling of Ceres and NLopt and the move limits of
// NLopt mean something for a function whose features are O(1) in its coordinates.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "solvers/objective.h"

namespace ergo {

// Shared geometry of the analytic objectives: coordinates in mm, moves in metres.
// Shared geometry of the analytic objectives: every coordinate is a vertex.
class AnalyticObjective : public Objective {
 public:
  explicit AnalyticObjective(double metres_per_unit);
  double LargestMove(const Eigen::VectorXd& dx) const override;  // metres_per_unit · ‖dx‖∞
  double BoxHalfWidthForMove(double move) const override { return move / metres_per_unit_; }
  double LengthScale() const override { return 1e-3 / metres_per_unit_; }  // 1 mm
  double metres_per_unit() const { return metres_per_unit_; }
  std::vector<std::string> TermNames() const override { return {"f"}; }

  // The minimiser; the minimum is 0.
  virtual Eigen::VectorXd Minimizer() const = 0;

 private:
  double metres_per_unit_;
};

// f(x) = ½ (x − x*)ᵀ A (x − x*), A = Qᵀ diag(λ) Q with λ log-spaced from 1 to `condition`
// and Q a random rotation (seeded), so the ill-conditioning is not axis-aligned unless
// `rotated` is false; x* uniform in [−1, 1]ⁿ.
class IllConditionedQuadratic : public AnalyticObjective {
 public:
  IllConditionedQuadratic(int n, double condition, unsigned seed = 1, bool rotated = true,
                          double metres_per_unit = 1e-2);
  int NumParameters() const override { return static_cast<int>(minimizer_.size()); }
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  std::string Describe() const override;
  Eigen::VectorXd Minimizer() const override { return minimizer_; }
  const Eigen::MatrixXd& hessian() const { return hessian_; }

 private:
  Eigen::MatrixXd hessian_;
  Eigen::VectorXd minimizer_;
  double condition_;
};

// The extended Rosenbrock function (n even): Σ_i 100 (x_{2i+1} − x_{2i}²)² + (1 − x_{2i})²,
// n/2 independent banana valleys; unique minimum 0 at (1, …, 1). Standard start:
// (−1.2, 1, −1.2, 1, …).
class ExtendedRosenbrock : public AnalyticObjective {
 public:
  explicit ExtendedRosenbrock(int n, double metres_per_unit = 1e-2);
  int NumParameters() const override { return n_; }
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  std::string Describe() const override;
  Eigen::VectorXd Minimizer() const override { return Eigen::VectorXd::Ones(n_); }
  Eigen::VectorXd StandardStart() const;

 private:
  int n_;
};

}  // namespace ergo
