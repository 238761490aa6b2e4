#include "ergo/ergonomics/pressure_grid.h"

#include <cmath>

namespace ergo {

double PressureGrid::PressureAt(const Eigen::Vector2d& q) const {
  if (!(pitch > 0) || pressure.size() == 0) return 0;
  // Continuous index of q among the cell centres: centre (r, c) sits at (c, r).
  const double u = (q.x() - origin.x()) / pitch - 0.5;
  const double v = (q.y() - origin.y()) / pitch - 0.5;
  if (!(u > -1) || !(v > -1) || !(u < static_cast<double>(columns())) ||
      !(v < static_cast<double>(rows())))
    return 0;
  const double c0 = std::floor(u), r0 = std::floor(v);
  const double fu = u - c0, fv = v - r0;
  auto value = [&](double r, double c) {
    if (r < 0 || c < 0 || r >= static_cast<double>(rows()) || c >= static_cast<double>(columns()))
      return 0.0;  // the ring of empty cells around the plate
    return pressure(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
  };
  return (1 - fv) * ((1 - fu) * value(r0, c0) + fu * value(r0, c0 + 1)) +
         fv * ((1 - fu) * value(r0 + 1, c0) + fu * value(r0 + 1, c0 + 1));
}

}  // namespace ergo
