#include "ergo/ergonomics/pressure_cost.h"

#include <cmath>

#include <glog/logging.h>

namespace ergo {

PressureSmoothing MakePressureSmoothing(const TriMesh& surface,
                                        const PressureCostOptions& options) {
  if (options.smoothing_radius > 0)
    return PressureSmoothing::Helmholtz(surface, options.smoothing_radius);
  return PressureSmoothing::Umbrella(surface.triangles, surface.vertices.rows());
}

SurfacePressure EvaluateSurfacePressure(const Eigen::VectorXd& force_magnitude,
                                        const Eigen::VectorXd& area,
                                        const PressureSmoothing& smoothing,
                                        const PressureCostOptions& options) {
  const Eigen::Index n = force_magnitude.size();
  CHECK_EQ(area.size(), n);
  CHECK_EQ(smoothing.size(), n);
  CHECK(options.exponent >= 2 && options.exponent <= 4) << "exponent must be 2, 3 or 4";
  CHECK(options.smoothing >= 0 && options.smoothing <= 1) << "λ_p must lie in [0, 1]";
  const int e = options.exponent;
  const double lambda = options.smoothing;

  SurfacePressure out;
  out.pressure = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (force_magnitude[i] == 0) continue;
    CHECK_GT(area[i], 0.0) << "vertex " << i << " carries force but has no area";
    out.pressure[i] = force_magnitude[i] / area[i];
  }
  // P̄ = (I − λ(I − S)) P; with λ ∈ [0,1] and an averaging S, P̄ ≥ 0 (up to round-off, and
  // the small undershoots of a Helmholtz filter on obtuse triangles, clamped below).
  out.smoothed = smoothing.Apply(out.pressure, lambda);
  Eigen::VectorXd power_e(n), power_e1(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double p = std::max(out.smoothed[i], 0.0);  // guard −0 / round-off
    power_e1[i] = std::pow(p, e - 1);
    power_e[i] = power_e1[i] * p;
  }
  out.cost = area.dot(power_e);
  // ∂cost/∂P = (I − λ(I − S))ᵀ (s ∘ e P̄^{e−1}); then P = L/s.
  const Eigen::VectorXd weighted = (area.array() * e * power_e1.array()).matrix();
  const Eigen::VectorXd d_pressure = smoothing.ApplyTransposed(weighted, lambda);
  out.d_force_magnitude = Eigen::VectorXd::Zero(n);
  out.d_area = power_e;  // explicit s_i in Σ s_i P̄_i^e
  for (Eigen::Index i = 0; i < n; ++i) {
    if (area[i] <= 0) continue;
    out.d_force_magnitude[i] = d_pressure[i] / area[i];
    out.d_area[i] -= d_pressure[i] * out.pressure[i] / area[i];
  }
  return out;
}

}  // namespace ergo
