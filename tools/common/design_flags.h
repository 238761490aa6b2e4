// The design problem's flags, shared by ergo_optimize and ergo_compare so that one flagfile
// (data/SCENARIO.flags) poses the same problem to both: the pressure exponent and smoothing,
// ψ's Taubin operator, the contact stiffness (the scenario's, a number, or calibrated), and
// the smoothness weight γ (a number, or auto: κ·10^j with ζ(x₀) = κψ(x₀)).
#pragma once

#include <string>

#include "ergo/design/design_problem.h"
#include "problems/scenario.h"

namespace ergo {

// Applies --exponent, --pressure_smoothing, --taubin_* and --contact_stiffness to
// scenario->design (calibrating κ on the initial support for --contact_stiffness=auto; the
// start pose stays where the scene put it, above the support). Prints what it decided.
// Throws InputError naming the flag for unusable values.
void ApplyDesignFlags(Scenario* scenario);

// --robust_placements (1, 3 or 5; checked), --robust_shift_mm in metres and
// --robust_tilt_deg in radians: the objective averaged over those placements
// (solvers/robust_design_objective.h).
int RobustPlacementsFlag();
double RobustShiftFlag();
double RobustTiltFlag();

// γ from --gamma/--gamma_power, set on `problem` and returned. Prints how it was chosen.
// Throws InputError when auto cannot be computed (e.g. ψ(x₀) = 0). `at_x0`, if given, is an
// evaluation of x₀ already made (ok), so auto needs no solve of its own.
double ApplyGammaFlags(DesignProblem* problem, const DesignEvaluation* at_x0 = nullptr);

}  // namespace ergo
