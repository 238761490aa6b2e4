#include "solvers/analytic_objectives.h"

#include <cmath>
#include <random>

#include <glog/logging.h>
#include <Eigen/QR>

namespace ergo {

AnalyticObjective::AnalyticObjective(double metres_per_unit) : metres_per_unit_(metres_per_unit) {
  CHECK_GT(metres_per_unit, 0.0);
}

double AnalyticObjective::LargestMove(const Eigen::VectorXd& dx) const {
  return metres_per_unit_ * dx.lpNorm<Eigen::Infinity>();
}

IllConditionedQuadratic::IllConditionedQuadratic(int n, double condition, unsigned seed,
                                                 bool rotated, double metres_per_unit)
    : AnalyticObjective(metres_per_unit), condition_(condition) {
  CHECK_GT(n, 0);
  CHECK_GE(condition, 1.0);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd eigenvalues(n);
  for (int i = 0; i < n; ++i)
    eigenvalues[i] = n == 1 ? 1.0 : std::pow(condition, static_cast<double>(i) / (n - 1));
  Eigen::MatrixXd rotation = Eigen::MatrixXd::Identity(n, n);
  if (rotated) {
    Eigen::MatrixXd random_matrix(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) random_matrix(i, j) = uniform(random);
    rotation = Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix).householderQ();
  }
  hessian_ = rotation.transpose() * eigenvalues.asDiagonal() * rotation;
  hessian_ = 0.5 * (hessian_ + hessian_.transpose()).eval();  // exactly symmetric
  minimizer_.resize(n);
  for (int i = 0; i < n; ++i) minimizer_[i] = uniform(random);
}

ObjectiveValue IllConditionedQuadratic::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  CHECK_EQ(x.size(), minimizer_.size());
  ObjectiveValue out;
  const Eigen::VectorXd r = x - minimizer_;
  const Eigen::VectorXd g = hessian_ * r;
  out.phi = 0.5 * r.dot(g);
  out.terms = {{"f", 1, out.phi}};
  out.ok = std::isfinite(out.phi);
  out.message = out.ok ? "ok" : "non-finite value";
  if (with_gradient && out.ok) out.gradient = g;
  return out;
}

std::unique_ptr<Objective> IllConditionedQuadratic::Clone() const {
  return std::make_unique<IllConditionedQuadratic>(*this);
}

std::string IllConditionedQuadratic::Describe() const {
  return std::to_string(NumParameters()) + "-D quadratic, condition " + std::to_string(condition_);
}

ExtendedRosenbrock::ExtendedRosenbrock(int n, double metres_per_unit)
    : AnalyticObjective(metres_per_unit), n_(n) {
  CHECK(n > 0 && n % 2 == 0) << "the extended Rosenbrock function needs an even dimension";
}

ObjectiveValue ExtendedRosenbrock::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  CHECK_EQ(x.size(), n_);
  ObjectiveValue out;
  if (with_gradient) out.gradient = Eigen::VectorXd::Zero(n_);
  double f = 0;
  for (int i = 0; i + 1 < n_; i += 2) {
    const double a = x[i + 1] - x[i] * x[i], b = 1 - x[i];
    f += 100 * a * a + b * b;
    if (with_gradient) {
      out.gradient[i] = -400 * a * x[i] - 2 * b;
      out.gradient[i + 1] = 200 * a;
    }
  }
  out.phi = f;
  out.terms = {{"f", 1, f}};
  out.ok = std::isfinite(f);
  out.message = out.ok ? "ok" : "non-finite value";
  if (!out.ok) out.gradient.resize(0);
  return out;
}

std::unique_ptr<Objective> ExtendedRosenbrock::Clone() const {
  return std::make_unique<ExtendedRosenbrock>(*this);
}

std::string ExtendedRosenbrock::Describe() const {
  return std::to_string(n_) + "-D extended Rosenbrock";
}

Eigen::VectorXd ExtendedRosenbrock::StandardStart() const {
  Eigen::VectorXd x(n_);
  for (int i = 0; i < n_; ++i) x[i] = i % 2 == 0 ? -1.2 : 1.0;
  return x;
}

}  // namespace ergo
