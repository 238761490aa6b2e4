// The smoothstep ramp of the generated bodies' shapes: 0 below edge0, 1 above edge1, C¹.
#pragma once

#include <algorithm>

namespace ergo {

inline double SmoothStep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace ergo
