#include "ergo/equilibrium/calibrate_contact_stiffness.h"

#include <cmath>

namespace ergo {

CalibrationResult CalibrateContactStiffness(EquilibriumSolver& solver, const Support& support,
                                            const BodyState& start, double target_penetration,
                                            const CalibrationOptions& options,
                                            EquilibriumResult* last) {
  const double initial = solver.options().contact_stiffness;
  BodyState warm = start;
  EquilibriumResult latest;
  auto penetration_at = [&](double k) -> std::optional<double> {
    solver.set_contact_stiffness(k);
    EquilibriumResult result = solver.Solve(support, warm);
    if (options.progress)
      options.progress(k, result.converged ? result.max_penetration : std::nan(""));
    if (!result.converged) return std::nullopt;
    warm = result.state;
    latest = result;
    return result.max_penetration;
  };
  CalibrationOptions used = options;
  used.initial_stiffness = initial;
  const CalibrationResult calibration =
      CalibrateStiffness(penetration_at, target_penetration, used);
  solver.set_contact_stiffness(calibration.stiffness > 0 ? calibration.stiffness : initial);
  if (last) *last = latest;
  return calibration;
}

}  // namespace ergo
