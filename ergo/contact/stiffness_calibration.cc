#include "ergo/contact/stiffness_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glog/logging.h>

namespace ergo {

std::string CalibrationResult::BriefReport() const {
  std::ostringstream out;
  out << (converged ? "converged" : "not converged") << ": κ = " << stiffness << " Pa/m gives "
      << penetration * 1e3 << " mm (target " << target * 1e3 << " mm) after " << evaluations
      << " solves";
  if (!converged) out << " — " << message;
  return out.str();
}

CalibrationResult CalibrateStiffness(
    const std::function<std::optional<double>(double k)>& max_penetration_at, double target,
    const CalibrationOptions& options) {
  CHECK_GT(target, 0.0);
  CHECK_GT(options.initial_stiffness, 0.0);
  CHECK_GT(options.min_stiffness, 0.0);
  CHECK_LT(options.min_stiffness, options.max_stiffness);
  CHECK_GT(options.max_evaluations, 0);
  CHECK_GT(options.min_exponent, 0.0);
  CHECK_LE(options.min_exponent, options.max_exponent);

  CalibrationResult result;
  result.target = target;
  const double log_target = std::log(target);
  const double log_min = std::log(options.min_stiffness);
  const double log_max = std::log(options.max_stiffness);
  const double infinity = std::numeric_limits<double>::infinity();

  // x = log k. Bracket: `too_soft` is the largest x seen with penetration above the target,
  // `too_stiff` the smallest with penetration below it.
  double x = std::clamp(std::log(options.initial_stiffness), log_min, log_max);
  double too_soft = -infinity, too_stiff = infinity;
  bool have_previous = false;  // previous usable sample (x, log penetration)
  double previous_x = 0, previous_y = 0;
  bool have_success = false;
  double last_success_x = 0;
  double best_miss = infinity;
  bool have_best = false;

  while (result.evaluations < options.max_evaluations) {
    const double k = std::exp(x);
    const std::optional<double> penetration = max_penetration_at(k);
    ++result.evaluations;

    if (!penetration || !std::isfinite(*penetration) || *penetration < 0) {
      if (!have_success) {
        std::ostringstream out;
        out << "the equilibrium failed at κ = " << k << " Pa/m before any stiffness worked";
        result.message = out.str();
        return result;
      }
      // Back off half-way (in log k) towards the last stiffness that worked.
      x = 0.5 * (x + last_success_x);
      continue;
    }
    have_success = true;
    last_success_x = x;

    const double pen = *penetration;
    const double miss = pen > 0 ? std::abs(std::log(pen) - log_target) : infinity;
    if (!have_best || miss <= best_miss) {  // ties: the later, more refined k
      have_best = true;
      best_miss = miss;
      result.stiffness = k;
      result.penetration = pen;
    }
    if (std::abs(pen - target) <= options.relative_tolerance * target) {
      result.stiffness = k;
      result.penetration = pen;
      result.converged = true;
      result.message = "penetration within tolerance";
      return result;
    }
    if (pen > target) {
      too_soft = std::max(too_soft, x);
    } else {
      too_stiff = std::min(too_stiff, x);
    }

    double next;
    if (pen > 0) {
      // Newton step on log pen = c − α log k, α from the last two samples (secant), else
      // α = 1 (penetration ∝ 1/k for a fixed contact set carrying a fixed load).
      const double y = std::log(pen);
      double alpha = 1.0;
      if (have_previous && previous_x != x) alpha = -(y - previous_y) / (x - previous_x);
      if (!std::isfinite(alpha)) alpha = 1.0;
      alpha = std::clamp(alpha, options.min_exponent, options.max_exponent);
      next = x + (y - log_target) / alpha;
      have_previous = true;
      previous_x = x;
      previous_y = y;
    } else {
      next = x - std::log(10.0);  // no penetration at all: a decade softer
    }
    if (std::isfinite(too_soft) && std::isfinite(too_stiff)) {
      if (too_stiff - too_soft < 1e-9) {
        result.message =
            "the bracket collapsed: the penetration jumps across the target (the contact set "
            "changes discontinuously with k)";
        return result;
      }
      if (!(next > too_soft && next < too_stiff)) next = 0.5 * (too_soft + too_stiff);
    }
    next = std::clamp(next, log_min, log_max);
    if (next == x) {
      std::ostringstream out;
      out << "stuck at the stiffness limit κ = " << std::exp(x) << " Pa/m";
      result.message = out.str();
      return result;
    }
    x = next;
  }
  std::ostringstream out;
  out << "no stiffness within tolerance after " << result.evaluations << " evaluations";
  result.message = out.str();
  return result;
}

}  // namespace ergo
