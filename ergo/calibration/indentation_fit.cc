#include "ergo/calibration/indentation_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <ceres/ceres.h>
#include <Eigen/Dense>

namespace ergo {
namespace {

// r = (F(δ − c; e^a, e^b) − F_measured) / scale over a = ln E, b = ln h and c; b is ignored
// for the half-space, and F = 0 before contact.
class IndentationResidual : public ceres::SizedCostFunction<1, 1, 1, 1> {
 public:
  IndentationResidual(const SphericalIndenter& indenter, double indentation, double force,
                      double scale, bool half_space)
      : indenter_(indenter),
        indentation_(indentation),
        force_(force),
        scale_(scale),
        half_space_(half_space) {}

  bool Evaluate(double const* const* parameters, double* residual,
                double** jacobians) const override {
    const double youngs = std::exp(parameters[0][0]);
    const double depth =
        half_space_ ? std::numeric_limits<double>::infinity() : std::exp(parameters[1][0]);
    const double travel = indentation_ - parameters[2][0];
    if (!std::isfinite(youngs) || youngs <= 0 || !(depth > 0) || !std::isfinite(travel))
      return false;
    IndentationForce law;  // all zero before contact
    if (travel > 0) law = LayeredIndentationForce(indenter_, youngs, depth, travel);
    residual[0] = (law.force - force_) / scale_;
    if (jacobians != nullptr) {
      if (jacobians[0] != nullptr) jacobians[0][0] = law.d_youngs_modulus * youngs / scale_;
      if (jacobians[1] != nullptr) jacobians[1][0] = half_space_ ? 0 : law.d_depth * depth / scale_;
      if (jacobians[2] != nullptr) jacobians[2][0] = -law.d_indentation / scale_;
    }
    return std::isfinite(residual[0]);
  }

 private:
  SphericalIndenter indenter_;
  double indentation_, force_, scale_;
  bool half_space_;
};

struct Readings {
  std::vector<double> indentation, force;
  double max_force = 0, max_indentation = 0;
};

// E that fits best for a fixed h (and no contact offset): F is linear in E.
double BestModulusForDepth(const Readings& readings, const SphericalIndenter& indenter,
                           double depth) {
  double numerator = 0, denominator = 0;
  for (size_t i = 0; i < readings.force.size(); ++i) {
    if (!(readings.indentation[i] > 0)) continue;
    const double g = LayeredIndentationForce(indenter, 1.0, depth, readings.indentation[i]).force;
    numerator += g * readings.force[i];
    denominator += g * g;
  }
  return numerator > 0 && denominator > 0 ? numerator / denominator : 1e4;
}

struct Solution {
  double log_modulus = 0, log_depth = 0, contact_offset = 0;
  double cost = std::numeric_limits<double>::infinity();
  bool usable = false, converged = false;
  std::string report;
};

Solution Solve(const Readings& readings, const IndentationFitOptions& options, double depth,
               bool fit_depth) {
  const bool half_space = std::isinf(depth) && !fit_depth;
  Solution solution;
  solution.log_modulus = std::log(BestModulusForDepth(readings, options.indenter, depth));
  solution.log_depth = half_space ? 0 : std::log(depth);
  ceres::Problem problem;
  for (size_t i = 0; i < readings.force.size(); ++i) {
    problem.AddResidualBlock(
        new IndentationResidual(options.indenter, readings.indentation[i], readings.force[i],
                                readings.max_force, half_space),
        nullptr, &solution.log_modulus, &solution.log_depth, &solution.contact_offset);
  }
  if (options.fit_contact_point) {
    problem.SetParameterLowerBound(&solution.contact_offset, 0, -0.5 * readings.max_indentation);
    problem.SetParameterUpperBound(&solution.contact_offset, 0, 0.5 * readings.max_indentation);
  } else {
    problem.SetParameterBlockConstant(&solution.contact_offset);
  }
  if (fit_depth) {
    // The layer is deeper than the deepest indentation.
    problem.SetParameterLowerBound(&solution.log_depth, 0,
                                   std::log(1.0001 * readings.max_indentation));
    problem.SetParameterUpperBound(&solution.log_depth, 0, std::log(options.max_depth));
  } else {
    problem.SetParameterBlockConstant(&solution.log_depth);
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.function_tolerance = 1e-14;
  solver.gradient_tolerance = 1e-14;
  solver.parameter_tolerance = 1e-12;
  solver.logging_type = ceres::SILENT;
  solver.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  solution.usable = summary.IsSolutionUsable();
  solution.converged = summary.termination_type == ceres::CONVERGENCE;
  solution.cost = summary.final_cost;
  solution.report = summary.message;
  return solution;
}

}  // namespace

ceres::CostFunction* NewIndentationResidual(const SphericalIndenter& indenter, double indentation,
                                            double force, double scale, bool half_space) {
  return new IndentationResidual(indenter, indentation, force, scale, half_space);
}

IndentationFit FitIndentationCurve(const std::vector<double>& indentation,
                                   const std::vector<double>& force,
                                   const IndentationFitOptions& options) {
  IndentationFit fit;
  Readings readings;
  for (size_t i = 0; i < indentation.size() && i < force.size(); ++i) {
    // Without a fitted contact point, the readings at and before it carry no information.
    if (!options.fit_contact_point && !(indentation[i] > 0)) continue;
    readings.indentation.push_back(indentation[i]);
    readings.force.push_back(force[i]);
    readings.max_force = std::max(readings.max_force, force[i]);
    readings.max_indentation = std::max(readings.max_indentation, indentation[i]);
  }
  fit.readings = static_cast<int>(readings.force.size());
  const int parameters = 1 + options.fit_depth + options.fit_contact_point;
  const int needed = 2 * parameters;
  if (fit.readings < needed) {
    const std::string unknowns = !options.fit_depth
                                     ? (options.fit_contact_point ? "E and the contact point" : "E")
                                 : options.fit_contact_point ? "E, the depth and the contact point"
                                                             : "E and the depth";
    fit.message = "has " + std::to_string(fit.readings) +
                  (options.fit_contact_point ? " readings" : " readings beyond the contact point") +
                  "; fitting " + unknowns + " needs " + std::to_string(needed);
    return fit;
  }
  if (!(readings.max_force > 0)) {
    fit.message = "has no positive force: the indenter never pressed";
    return fit;
  }
  if (!(readings.max_indentation > 0)) {
    fit.message = "has no reading beyond indentation 0: the tip never pressed in";
    return fit;
  }
  if (options.fit_depth && !(options.max_depth > 1.02 * readings.max_indentation)) {
    fit.message = "is indented as deep as the largest depth the fit may reach (max_depth)";
    return fit;
  }
  if (!options.fit_depth && !options.fit_contact_point &&
      !(options.depth > readings.max_indentation)) {
    fit.message = "is indented deeper than the layer's depth";
    return fit;
  }

  Solution best;
  if (!options.fit_depth) {
    best = Solve(readings, options, options.depth, false);
  } else {
    // Several first guesses: the misfit as a function of h can have a shallow valley.
    std::vector<double> guesses;
    if (options.depth > 0 && std::isfinite(options.depth)) guesses.push_back(options.depth);
    for (double factor : {1.5, 3.0, 6.0, 12.0, 24.0})
      guesses.push_back(factor * readings.max_indentation);
    for (double guess : guesses) {
      guess = std::clamp(guess, 1.01 * readings.max_indentation, options.max_depth);
      const Solution trial = Solve(readings, options, guess, true);
      if (trial.usable && trial.cost < best.cost) best = trial;
    }
  }
  if (!best.usable) {
    fit.message = "did not converge (" + best.report + ")";
    return fit;
  }
  fit.converged = best.converged;
  if (!best.converged) fit.message = "stopped before convergence (" + best.report + ")";
  fit.youngs_modulus = std::exp(best.log_modulus);
  fit.depth = options.fit_depth ? std::exp(best.log_depth) : options.depth;
  fit.contact_offset = best.contact_offset;

  // Residuals and the Gauss–Newton covariance at the solution, over (ln E[, ln h][, c]).
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(fit.readings, parameters);
  Eigen::VectorXd residual(fit.readings);
  double deepest = 0;
  for (int i = 0; i < fit.readings; ++i) {
    const double travel = readings.indentation[i] - fit.contact_offset;
    IndentationForce law;
    if (travel > 0)
      law = LayeredIndentationForce(options.indenter, fit.youngs_modulus, fit.depth, travel);
    residual[i] = law.force - readings.force[i];
    int column = 0;
    jacobian(i, column++) = law.d_youngs_modulus * fit.youngs_modulus;          // ∂F/∂ln E
    if (options.fit_depth) jacobian(i, column++) = law.d_depth * fit.depth;     // ∂F/∂ln h
    if (options.fit_contact_point) jacobian(i, column++) = -law.d_indentation;  // ∂F/∂c
    fit.max_chi = std::max(fit.max_chi, law.chi);
    deepest = std::max(deepest, travel);
  }
  fit.max_strain = std::isinf(fit.depth) ? 0 : deepest / fit.depth;
  fit.rms_residual = std::sqrt(residual.squaredNorm() / fit.readings);
  fit.relative_rms = fit.rms_residual / readings.max_force;
  // At least two readings per unknown (checked above) leave n − p ≥ 1.
  const double variance = residual.squaredNorm() / (fit.readings - parameters);
  const Eigen::MatrixXd covariance =
      variance *
      (jacobian.transpose() * jacobian).completeOrthogonalDecomposition().pseudoInverse();
  auto standard_error = [&](int column) {
    return std::sqrt(std::max(0.0, covariance(column, column)));
  };
  fit.youngs_modulus_stderr = fit.youngs_modulus * standard_error(0);
  if (options.fit_depth) fit.depth_stderr = fit.depth * standard_error(1);
  if (options.fit_contact_point) fit.contact_offset_stderr = standard_error(parameters - 1);
  if (options.fit_depth) {
    fit.depth_at_bound = fit.depth > 0.999 * options.max_depth;
    if (fit.depth_at_bound) {
      fit.message = "the depth is not determined: the curve looks like a half-space's up to " +
                    std::to_string(options.max_depth) + " m; measure the depth and give it";
    } else if (fit.depth_stderr > 0.25 * fit.depth) {
      fit.message =
          "the depth is poorly determined (±" +
          std::to_string(static_cast<int>(std::lround(100 * fit.depth_stderr / fit.depth))) +
          " %): indent deeper, or measure the depth and give it";
    }
  }
  if (fit.message.empty() && fit.max_chi > 1) {
    // Dimitriadis et al. validated the series for χ < 1.
    char value[32];
    std::snprintf(value, sizeof(value), "%.2f", fit.max_chi);
    fit.message =
        std::string("indented beyond the law's range (largest √(Rδ)/h ") + value + " > 1)";
  } else if (fit.message.empty() && fit.max_strain > 0.25) {
    // The law is small-strain; ergo's neo-Hookean FEM is a few per cent stiffer by δ/h = 0.2
    // (ergo/calibration/README.md), and more beyond.
    char value[32];
    std::snprintf(value, sizeof(value), "%.2f", fit.max_strain);
    fit.message = std::string("indented to δ/h = ") + value +
                  ": beyond about 0.2 finite strain stiffens the tissue and E reads high";
  }
  return fit;
}

std::string DescribeFit(const IndentationFit& fit) {
  if (fit.youngs_modulus <= 0) return "no fit: " + fit.message;
  char text[256];
  std::snprintf(text, sizeof(text), "E = %.4g ± %.2g kPa", 1e-3 * fit.youngs_modulus,
                1e-3 * fit.youngs_modulus_stderr);
  std::string line = text;
  if (std::isinf(fit.depth)) {
    line += ", half-space";
  } else {
    std::snprintf(text, sizeof(text), ", h = %.4g", 1e3 * fit.depth);
    line += text;
    if (fit.depth_stderr > 0) {
      std::snprintf(text, sizeof(text), " ± %.2g", 1e3 * fit.depth_stderr);
      line += text;
    }
    line += " mm";
  }
  if (fit.contact_offset != 0 || fit.contact_offset_stderr > 0) {
    std::snprintf(text, sizeof(text), ", contact at %+.3g ± %.2g mm", 1e3 * fit.contact_offset,
                  1e3 * fit.contact_offset_stderr);
    line += text;
  }
  std::snprintf(text, sizeof(text), ", rms %.2g %% of the peak force", 100 * fit.relative_rms);
  line += text;
  if (!fit.message.empty()) line += " (" + fit.message + ")";
  return line;
}

}  // namespace ergo
