// Tissue calibration (paper §3.1): Young's modulus — and, when asked, the layer's depth and
// where the tip first touched — of one measured point from its force–indentation curve, by
// least squares on the layered indentation law (layered_indentation.h) with Ceres. The
// unknowns are ln E and ln h (both positive, and of very different sizes) and the contact
// offset c (the logged travel at first contact: the law is taken at δ − c, zero before it);
// the residuals are the force misfits divided by the curve's largest force. Standard errors come
// from the Gauss–Newton covariance σ²(JᵀJ)⁻¹ at the solution with σ² = Σr²/(n − p).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "ergo/calibration/layered_indentation.h"

namespace ceres {
class CostFunction;
}

namespace ergo {

struct IndentationFitOptions {
  SphericalIndenter indenter;
  // false: h is `depth` (∞: the half-space); true: h is fitted too, from several first
  // guesses (`depth` > 0 is one of them), between the deepest indentation and max_depth.
  bool fit_depth = false;
  double depth = std::numeric_limits<double>::infinity();  // m
  double max_depth = 0.2;                                  // m, the fitted depth's bound
  // true: the contact offset c is fitted too, within ± half the deepest travel, and every
  // reading counts (those before contact say where it is); false: c = 0 and readings at
  // δ ≤ 0 are left out.
  bool fit_contact_point = false;
  int max_iterations = 200;
};

struct IndentationFit {
  bool converged = false;
  std::string message;               // why not, or what to beware of ("" when nothing)
  double youngs_modulus = 0;         // Pa
  double depth = 0;                  // m (given or fitted; ∞ for the half-space)
  double youngs_modulus_stderr = 0;  // Pa
  double depth_stderr = 0;           // m; 0 when given
  bool depth_at_bound = false;       // the fitted depth ended on max_depth: not determined
  double contact_offset = 0;         // m: c, the logged travel at first contact (0 if not fitted)
  double contact_offset_stderr = 0;  // m
  double rms_residual = 0;           // N
  double relative_rms = 0;           // rms / largest force
  double max_chi = 0;                // largest √(R(δ − c))/h of the readings
  double max_strain = 0;             // largest (δ − c)/h
  int readings = 0;                  // readings used
};

// Fits the curve (δ_i, F_i). Needs readings: at least 2 (E only), 4 (E and h), one more with
// the contact point, and a largest force > 0; otherwise returns converged = false with the
// reason.
IndentationFit FitIndentationCurve(const std::vector<double>& indentation,
                                   const std::vector<double>& force,
                                   const IndentationFitOptions& options);

// The fit's residual for one reading, r = (F(δ − c; e^a, e^b) − force) / scale over the
// parameter blocks a = ln E, b = ln h (ignored when half_space) and c (m), F = 0 for δ ≤ c
// (C¹ there: F grows as (δ − c)^{3/2}), with its analytic Jacobian. The caller owns it (a
// ceres::Problem takes ownership).
ceres::CostFunction* NewIndentationResidual(const SphericalIndenter& indenter, double indentation,
                                            double force, double scale, bool half_space);

// One line: "E = 48.2 ± 0.6 kPa, h = 15.9 ± 0.4 mm, rms 0.4 % of the peak force".
std::string DescribeFit(const IndentationFit& fit);

}  // namespace ergo
