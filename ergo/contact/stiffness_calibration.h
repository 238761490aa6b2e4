// Penalty-stiffness calibration (paper §3.5): choose the contact stiffness k of Eq. 10 so
// that the largest penetration at static equilibrium is a target depth (0.3 mm in the
// paper). The caller supplies "k ↦ max penetration at equilibrium"; the search uses the
// model penetration ∝ k^(−α) (α = 1 for a fixed contact set carrying a fixed load; see
// README.md) with secant steps in log k and a bracket. Units: depths in m; k in the
// caller's units (the equilibrium's κ is in Pa/m: ergo/contact/surface_contact.h).
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace ergo {

struct CalibrationOptions {
  // First stiffness tried (κ, Pa/m: 1e8 gives 30 kPa at 0.3 mm).
  double initial_stiffness = 1e8;
  // Converged when |penetration − target| ≤ relative_tolerance · target. 5 % keeps the
  // paper's 0.3 mm within 0.015 mm, half the ±0.03 mm the equilibrium acceptance allows.
  double relative_tolerance = 0.05;
  // Cap on calls of the penetration function (each is a full equilibrium solve).
  int max_evaluations = 12;
  // The search never leaves [min_stiffness, max_stiffness].
  double min_stiffness = 1e-3;
  double max_stiffness = 1e15;
  // Clamp on the fitted exponent α of penetration ∝ k^(−α), guarding the secant step
  // against noise and non-monotone data.
  double min_exponent = 0.1;
  double max_exponent = 3.0;
  // Called after each penetration evaluation (k, its max penetration in m or NaN when the
  // solve failed): progress lines for long calibrations.
  std::function<void(double stiffness, double penetration)> progress;
};

struct CalibrationResult {
  double stiffness = 0.0;    // the k whose penetration is nearest the target (log ratio)
  double penetration = 0.0;  // max penetration at `stiffness`, m
  double target = 0.0;       // the requested penetration, m
  int evaluations = 0;       // calls of the penetration function
  bool converged = false;    // |penetration − target| within tolerance
  std::string message;       // why the search stopped

  // One line, e.g. "converged: κ = 2.1e+08 Pa/m gives 0.301 mm (target 0.3 mm) after 3 solves".
  std::string BriefReport() const;
};

// Finds k with max_penetration_at(k) ≈ target. max_penetration_at returns std::nullopt
// when its equilibrium solve fails; the search then backs off towards the last k that
// worked (or stops if none has). target > 0 (CHECKed).
CalibrationResult CalibrateStiffness(
    const std::function<std::optional<double>(double k)>& max_penetration_at, double target = 3e-4,
    const CalibrationOptions& options = CalibrationOptions());

}  // namespace ergo
