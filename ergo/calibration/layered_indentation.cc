#include "ergo/calibration/layered_indentation.h"

#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {

Eigen::Vector4d LayerCorrectionCoefficients(double nu, LayerBase base) {
  CHECK(nu > -1 && nu <= 0.5) << "Poisson's ratio " << nu;
  // Dimitriadis et al. 2002, eqs. 11–12: α₀, β₀ fitted to the exact layer solutions.
  double alpha = 0, beta = 0;
  if (base == LayerBase::kBonded) {
    alpha = -(1.2876 - 1.4678 * nu + 1.3442 * nu * nu) / (1 - nu);
    beta = (0.6387 - 1.0277 * nu + 1.5164 * nu * nu) / (1 - nu);
  } else {
    alpha = -0.347 * (3 - 2 * nu) / (1 - nu);
    beta = 0.056 * (5 - 2 * nu) / (1 - nu);
  }
  const double pi = M_PI, pi2 = pi * pi;
  Eigen::Vector4d c;
  c[0] = -2 * alpha / pi;
  c[1] = 4 * alpha * alpha / pi2;
  c[2] = -8 / (pi2 * pi) * (alpha * alpha * alpha + 4 * pi2 / 15 * beta);
  c[3] = 16 * alpha / (pi2 * pi2) * (alpha * alpha * alpha + 3 * pi2 / 5 * beta);
  return c;
}

IndentationForce LayeredIndentationForce(const SphericalIndenter& indenter, double youngs_modulus,
                                         double depth, double indentation) {
  CHECK_GT(indenter.radius, 0);
  CHECK_GT(youngs_modulus, 0);
  CHECK_GT(depth, 0);
  CHECK_GE(indentation, 0);
  const double nu = indenter.poisson_ratio, radius = indenter.radius;
  const double hertz = 4 / (3 * (1 - nu * nu)) * std::sqrt(radius);  // F/(E δ^{3/2}) at χ = 0
  IndentationForce result;
  const bool half_space = std::isinf(depth);
  result.chi = half_space ? 0 : std::sqrt(radius * indentation) / depth;
  const double chi = result.chi;
  const Eigen::Vector4d c = LayerCorrectionCoefficients(nu, indenter.base);
  const double series = 1 + chi * (c[0] + chi * (c[1] + chi * (c[2] + chi * c[3])));
  const double series_slope = c[0] + chi * (2 * c[1] + chi * (3 * c[2] + chi * 4 * c[3]));
  const double root = std::sqrt(indentation);
  const double power = indentation * root;  // δ^{3/2}
  result.force = hertz * youngs_modulus * power * series;
  result.d_youngs_modulus = hertz * power * series;
  // ∂χ/∂h = −χ/h; ∂χ/∂δ = χ/(2δ), so δ^{3/2}·P'(χ)·χ/(2δ) = ½ δ^{1/2} χ P'(χ).
  result.d_depth = half_space ? 0 : -hertz * youngs_modulus * power * series_slope * chi / depth;
  result.d_indentation = hertz * youngs_modulus * root * (1.5 * series + 0.5 * chi * series_slope);
  return result;
}

}  // namespace ergo
