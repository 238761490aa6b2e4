// Finite-difference checks used by every derivative test.
//
// Central differences have truncation error O(h^2) and round-off error O(eps*|f|/h); no
// single step is right for every function, so each check sweeps the step over several
// decades and keeps the best agreement (the sweep is reported on failure). Directions:
// random unit vectors, the analytic gradient itself (DESIGN.md §6: a sign-flipped term
// that random directions average out is caught along the gradient), and coordinates.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace ergo::testing {

using ScalarFunction = std::function<double(const Eigen::VectorXd&)>;
using VectorFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct SweepResult {
  double best_relative_error = 0.0;  // min over steps of |fd - analytic| / scale
  double best_step = 0.0;
  std::string report;  // one line per step, for failure messages
};

// Steps h = base * 10^-k, k = 0..count-1.
std::vector<double> StepSweep(double base = 1e-2, int count = 7);

// Directional derivative of f at x along unit direction d by central differences,
// compared with `analytic` (= grad·d). Relative to max(|analytic|, scale_floor).
SweepResult CheckDirectional(const ScalarFunction& f, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& d, double analytic, double scale_floor,
                             const std::vector<double>& steps);

// Jacobian-vector product J·d of vector function g by central differences, compared with
// `analytic`; error is the max-norm relative to max(|analytic|_inf, scale_floor).
SweepResult CheckJacobianVector(const VectorFunction& g, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& d, const Eigen::VectorXd& analytic,
                                double scale_floor, const std::vector<double>& steps);

// Runs CheckDirectional along `random_directions` random unit vectors, along the
// normalised gradient, and along every coordinate (if x.size() <= max_coordinates);
// returns the worst best-relative-error and fills `report` with the worst case.
double WorstGradientError(const ScalarFunction& f, const Eigen::VectorXd& gradient,
                          const Eigen::VectorXd& x, double scale_floor,
                          const std::vector<double>& steps, int random_directions,
                          int max_coordinates, unsigned seed, std::string* report);

// Same for a Jacobian (e.g. gradient -> Hessian): columns checked along directions.
double WorstJacobianError(const VectorFunction& g, const Eigen::MatrixXd& jacobian,
                          const Eigen::VectorXd& x, double scale_floor,
                          const std::vector<double>& steps, int random_directions,
                          int max_coordinates, unsigned seed, std::string* report);

// The coordinates a component-wise check visits: the `largest` with the largest |gᵢ|, then
// about `spread` more evenly spaced; every coordinate when that would be most of them.
std::vector<Eigen::Index> CheckedComponents(const Eigen::VectorXd& gradient, int largest,
                                            int spread);

}  // namespace ergo::testing
