#include "tests/support/finite_difference.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace ergo::testing {

std::vector<double> StepSweep(double base, int count) {
  std::vector<double> steps;
  for (int k = 0; k < count; ++k) steps.push_back(base * std::pow(10.0, -k));
  return steps;
}

SweepResult CheckDirectional(const ScalarFunction& f, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& d, double analytic, double scale_floor,
                             const std::vector<double>& steps) {
  SweepResult result;
  result.best_relative_error = INFINITY;
  std::ostringstream out;
  const double scale = std::max(std::abs(analytic), scale_floor);
  for (double h : steps) {
    const double fd = (f(x + h * d) - f(x - h * d)) / (2 * h);
    const double error = std::abs(fd - analytic) / scale;
    out << "  h=" << h << " fd=" << fd << " analytic=" << analytic << " rel=" << error << "\n";
    if (error < result.best_relative_error) {
      result.best_relative_error = error;
      result.best_step = h;
    }
  }
  result.report = out.str();
  return result;
}

SweepResult CheckJacobianVector(const VectorFunction& g, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& d, const Eigen::VectorXd& analytic,
                                double scale_floor, const std::vector<double>& steps) {
  SweepResult result;
  result.best_relative_error = INFINITY;
  std::ostringstream out;
  const double scale = std::max(analytic.lpNorm<Eigen::Infinity>(), scale_floor);
  for (double h : steps) {
    const Eigen::VectorXd fd = (g(x + h * d) - g(x - h * d)) / (2 * h);
    const double error = (fd - analytic).lpNorm<Eigen::Infinity>() / scale;
    out << "  h=" << h << " |fd-analytic|_inf/scale=" << error << "\n";
    if (error < result.best_relative_error) {
      result.best_relative_error = error;
      result.best_step = h;
    }
  }
  result.report = out.str();
  return result;
}

namespace {

// Directions to test: random unit vectors, a preferred direction, coordinate axes.
std::vector<std::pair<std::string, Eigen::VectorXd>> Directions(Eigen::Index n,
                                                                const Eigen::VectorXd& preferred,
                                                                int random_directions,
                                                                int max_coordinates,
                                                                unsigned seed) {
  std::vector<std::pair<std::string, Eigen::VectorXd>> directions;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  for (int k = 0; k < random_directions; ++k) {
    Eigen::VectorXd d(n);
    for (Eigen::Index i = 0; i < n; ++i) d[i] = normal(rng);
    directions.emplace_back("random " + std::to_string(k), d.normalized());
  }
  if (preferred.size() == n && preferred.norm() > 0) {
    directions.emplace_back("along the analytic gradient", preferred.normalized());
  }
  if (n <= max_coordinates) {
    for (Eigen::Index i = 0; i < n; ++i) {
      directions.emplace_back("coordinate " + std::to_string(i), Eigen::VectorXd::Unit(n, i));
    }
  }
  return directions;
}

}  // namespace

double WorstGradientError(const ScalarFunction& f, const Eigen::VectorXd& gradient,
                          const Eigen::VectorXd& x, double scale_floor,
                          const std::vector<double>& steps, int random_directions,
                          int max_coordinates, unsigned seed, std::string* report) {
  double worst = 0.0;
  for (const auto& [name, d] :
       Directions(x.size(), gradient, random_directions, max_coordinates, seed)) {
    const SweepResult r = CheckDirectional(f, x, d, gradient.dot(d), scale_floor, steps);
    if (r.best_relative_error >= worst) {
      worst = r.best_relative_error;
      if (report) *report = "direction " + name + ":\n" + r.report;
    }
  }
  return worst;
}

double WorstJacobianError(const VectorFunction& g, const Eigen::MatrixXd& jacobian,
                          const Eigen::VectorXd& x, double scale_floor,
                          const std::vector<double>& steps, int random_directions,
                          int max_coordinates, unsigned seed, std::string* report) {
  double worst = 0.0;
  // Along the dominant row direction as the "preferred" direction for Jacobians.
  Eigen::VectorXd preferred;
  if (jacobian.rows() > 0) {
    Eigen::Index row;
    jacobian.rowwise().norm().maxCoeff(&row);
    preferred = jacobian.row(row).transpose();
  }
  for (const auto& [name, d] :
       Directions(x.size(), preferred, random_directions, max_coordinates, seed)) {
    const SweepResult r = CheckJacobianVector(g, x, d, jacobian * d, scale_floor, steps);
    if (r.best_relative_error >= worst) {
      worst = r.best_relative_error;
      if (report) *report = "direction " + name + ":\n" + r.report;
    }
  }
  return worst;
}

std::vector<Eigen::Index> CheckedComponents(const Eigen::VectorXd& gradient, int largest,
                                            int spread) {
  const Eigen::Index n = gradient.size();
  std::vector<Eigen::Index> all(n);
  for (Eigen::Index i = 0; i < n; ++i) all[i] = i;
  if (n <= largest + spread) return all;
  std::partial_sort(all.begin(), all.begin() + largest, all.end(),
                    [&](Eigen::Index a, Eigen::Index b) {
                      return std::abs(gradient[a]) > std::abs(gradient[b]);
                    });
  std::vector<Eigen::Index> chosen(all.begin(), all.begin() + largest);
  const Eigen::Index stride = std::max<Eigen::Index>(1, n / std::max(1, spread));
  for (Eigen::Index i = stride / 2; i < n; i += stride)
    if (std::find(chosen.begin(), chosen.end(), i) == chosen.end()) chosen.push_back(i);
  return chosen;
}

}  // namespace ergo::testing
