// Golden-section line search (paper §3.4, "the Golden ratio algorithm [54]") for the
// Newton step length η minimising φ(η) = E(y ⊕ η δy) − E(y), with collision detection
// redone inside φ at every trial. φ(0) = 0 and φ'(0) < 0 (a descent direction).
#pragma once

#include <functional>

namespace ergo {

struct GoldenSectionOptions {
  double armijo = 1e-4;          // accept η = 1 at once if φ(1) ≤ armijo·φ'(0)
  bool expand = false;           // grow η by the golden ratio while φ decreases (free fall)
  double max_step = 1e3;         // cap on η when expanding
  int max_evaluations = 30;      // cap on φ calls
  double relative_width = 1e-2;  // stop when the bracket is this narrow relative to η
  // |φ| at or below this is indistinguishable from round-off in E.
  double noise = 0.0;
  // When φ(1) fails the Armijo test, first try the minimiser of the quadratic through
  // φ(0) = 0, φ'(0) and φ(1) (clamped to [0.1, 0.5]) and accept it if it passes Armijo;
  // only otherwise bracket and reduce by golden sections. One or two trials per Newton step
  // instead of about ten (EquilibriumOptions::interpolated_line_search).
  bool interpolate = false;
};

struct GoldenSectionResult {
  double step = 0;   // η chosen (0 if no decrease was found)
  double value = 0;  // φ(step)
  int evaluations = 0;
  // True when φ(1) was within `noise` of 0: the energy cannot tell; the caller decides
  // (e.g. by the residual) whether to take the full step.
  bool undecidable = false;
};

// Minimises φ on η > 0 as described above. φ must be finite where it is defined; a
// non-finite value counts as +∞ (the step is shrunk).
GoldenSectionResult GoldenSectionSearch(const std::function<double(double)>& phi, double slope,
                                        const GoldenSectionOptions& options);

}  // namespace ergo
