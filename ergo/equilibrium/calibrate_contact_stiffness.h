// Contact stiffness calibration wired to the equilibrium (paper §3.5): k such that the
// largest penetration at equilibrium on the given support is the target (0.3 mm).
#pragma once

#include "ergo/contact/stiffness_calibration.h"
#include "ergo/equilibrium/equilibrium_solver.h"

namespace ergo {

// Runs CalibrateStiffness with full equilibrium solves from `start` (each solve
// warm-started from the previous one). Leaves `solver` set to the calibrated k (or, when
// the search fails, to the k it started with) and `last` holding the last converged state.
CalibrationResult CalibrateContactStiffness(EquilibriumSolver& solver, const Support& support,
                                            const BodyState& start, double target_penetration,
                                            const CalibrationOptions& options,
                                            EquilibriumResult* last);

}  // namespace ergo
