#include "ergo/equilibrium/golden_section.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {
namespace {

constexpr double kGolden = 1.6180339887498949;  // (1 + √5)/2

}  // namespace

GoldenSectionResult GoldenSectionSearch(const std::function<double(double)>& phi, double slope,
                                        const GoldenSectionOptions& options) {
  GoldenSectionResult result;
  auto evaluate = [&](double eta) {
    ++result.evaluations;
    const double value = phi(eta);
    return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
  };
  auto keep_best = [&](double eta, double value) {
    if (value < result.value) {
      result.value = value;
      result.step = eta;
    }
  };

  const double at_one = evaluate(1.0);
  keep_best(1.0, at_one);
  if (std::abs(at_one) <= options.noise) {
    result.undecidable = true;
    result.step = 1.0;
    result.value = at_one;
    return result;
  }

  // Bracket [a, c] around a minimiser with an interior point b, φ(b) < φ(a), φ(b) ≤ φ(c).
  double a = 0, fa = 0, b, fb, c, fc;
  if (at_one <= options.armijo * slope) {
    if (!options.expand) return result;
    // Walk out by the golden ratio while φ keeps decreasing.
    b = 1.0;
    fb = at_one;
    c = kGolden;
    fc = evaluate(c);
    while (fc < fb && c < options.max_step && result.evaluations < options.max_evaluations) {
      a = b, fa = fb;
      b = c, fb = fc;
      c = b * kGolden;
      fc = evaluate(c);
    }
    keep_best(b, fb);
    keep_best(c, fc);
    if (fc < fb) return result;  // still decreasing at the cap: take the farthest step
  } else {
    // φ(1) is too high: the minimiser lies in (0, 1). Seed the interior point: the
    // quadratic model's minimiser, accepted at once if it decreases enough, or 1/golden.
    c = 1.0;
    fc = at_one;
    b = 1.0 / kGolden;
    if (options.interpolate && std::isfinite(at_one)) {
      const double curvature = at_one - slope;  // φ ≈ slope·η + curvature·η² on [0, 1]
      b = curvature > 0 ? std::clamp(-slope / (2 * curvature), 0.1, 0.5) : 0.5;
    } else if (options.interpolate) {
      b = 0.5;  // φ(1) undefined (an inverted element): halve
    }
    fb = evaluate(b);
    keep_best(b, fb);
    if (options.interpolate && fb <= options.armijo * b * slope) return result;
    // Shrink until an interior point beats φ(0) = 0 (keeps the bracket valid).
    while (!(fb < fa) && result.evaluations < options.max_evaluations) {
      c = b, fc = fb;
      b = c / kGolden;
      fb = evaluate(b);
      keep_best(b, fb);
    }
    if (!(fb < fa)) return result;  // no decrease found: step stays 0 unless φ(1) < 0
  }

  // Golden-section reduction of [a, c] keeping the interior point b.
  while (c - a > options.relative_width * b && result.evaluations < options.max_evaluations) {
    // Probe the larger of the two sub-intervals at its golden point.
    const bool right = (c - b) > (b - a);
    const double x = right ? b + (c - b) / (kGolden * kGolden) : b - (b - a) / (kGolden * kGolden);
    const double fx = evaluate(x);
    keep_best(x, fx);
    if (fx < fb) {
      if (right)
        a = b, fa = fb;
      else
        c = b, fc = fb;
      b = x, fb = fx;
    } else {
      if (right)
        c = x, fc = fx;
      else
        a = x, fa = fx;
    }
  }
  (void)fa;
  (void)fc;
  return result;
}

}  // namespace ergo
