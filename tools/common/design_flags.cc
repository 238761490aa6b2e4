#include "tools/common/design_flags.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

#include <gflags/gflags.h>

#include "ergo/contact/support.h"
#include "ergo/equilibrium/calibrate_contact_stiffness.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/input_error.h"
#include "tools/common/flag_checks.h"

DEFINE_int32(exponent, 3, "pressure exponent e of ζ = Σ s P̄^e (2, 3 or 4)");
DEFINE_double(pressure_smoothing, 1.0, "λ_p of P̄ = (I − λ_p L) P, in [0, 1] (1 = the paper)");
DEFINE_string(gamma, "auto",
              "weight γ of the smoothness term ψ, or auto: κ·10^gamma_power with ζ(x₀) = κψ(x₀)");
DEFINE_int32(gamma_power, -1, "j in γ = κ·10^j when --gamma=auto");
DEFINE_double(taubin_lambda, 0.5, "ψ's Taubin λ");
DEFINE_double(taubin_mu, -0.53, "ψ's Taubin μ");
DEFINE_int32(taubin_iterations, 1, "ψ's Taubin iterations m");
DEFINE_string(contact_stiffness, "scenario",
              "contact stiffness κ in Pa/m (contact pressure per metre of penetration; a vertex's "
              "spring is κ times its area), auto (calibrate to --target_penetration), or "
              "scenario (the preset's)");
DEFINE_double(target_penetration, 3e-4, "max penetration --contact_stiffness=auto aims at, m");
DEFINE_string(design_metric, "vertex",
              "filtered design space: the optimiser's inner product on the design variables: "
              "vertex (one raw value per support vertex, weighted by its area) or l2 (scaled "
              "by the square root of the vertex area: the same metric on every support mesh)");
DEFINE_string(score_sides, "both",
              "which contact sides ζ counts: both (the paper's: skin vertices in the support "
              "and support vertices in the skin) or skin (the skin's side alone, what the "
              "person feels; mesh-consistent under one-way contact)");
DEFINE_bool(support_springs, false,
            "two-way contact: support vertices inside the skin push it too (default false: they "
            "are scored but push nothing, the paper's uni-directional equilibrium)");
DEFINE_int32(robust_placements, 1,
             "optimise the mean score over K placements of the body (1, 3 or 5: centred, and "
             "±--robust_shift_mm along the longer or both horizontal axes), each with its own "
             "equilibrium and adjoint, in parallel threads");
DEFINE_double(robust_shift_mm, 3,
              "--robust_placements: the shift of the off-centre placements, mm");
DEFINE_double(robust_tilt_deg, 0,
              "also average over the body held tilted by ± this much about each rotation axis "
              "across the load that the core lock holds (the placement checks' tilts: 2 more "
              "placements for the shoe and the chair, 4 for the mouse), degrees; 0: none");
DEFINE_string(line_search, "golden",
              "the equilibrium's Newton line search when the full step fails Armijo: golden "
              "(the paper's golden-section minimisation) or interpolated (the quadratic "
              "model's step first, golden sections only if it fails)");
DEFINE_int32(max_newton_iterations, 100,
             "the equilibrium's Newton iteration cap; a solve that reaches it has failed");
DEFINE_string(placement, "followed",
              "where the optimiser's evaluations start their equilibria: followed (warm from the "
              "nearest design evaluated before, the paper's; a path starts placed afresh and "
              "ergo_optimize keeps only designs a fresh placement confirms), anchored (one hop "
              "from the nearest fresh placement) or fresh (every design placed afresh: the "
              "score is a function of the design, but a noisy one)");

namespace ergo {
namespace {

double ParseNonNegative(const std::string& text, const std::string& flag) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(value >= 0) || !std::isfinite(value)) {
    throw InputError("--" + flag, "", "'" + text + "' is not a non-negative number",
                     "give a number, or see --help for the words it accepts");
  }
  return value;
}

}  // namespace

int RobustPlacementsFlag() {
  if (FLAGS_robust_placements != 1 && FLAGS_robust_placements != 3 &&
      FLAGS_robust_placements != 5) {
    throw InputError("--robust_placements", "",
                     "is " + std::to_string(FLAGS_robust_placements) + "; it must be 1, 3 or 5",
                     "1 = the centred placement only");
  }
  RequireInRange("robust_shift_mm", FLAGS_robust_shift_mm, 0.01, 50, "millimetres, e.g. 3");
  RequireInRange("robust_tilt_deg", FLAGS_robust_tilt_deg, 0, 30, "degrees, e.g. 1");
  return FLAGS_robust_placements;
}

double RobustShiftFlag() { return 1e-3 * FLAGS_robust_shift_mm; }

double RobustTiltFlag() { return FLAGS_robust_tilt_deg * M_PI / 180; }

void ApplyDesignFlags(Scenario* scenario) {
  RobustPlacementsFlag();
  DesignOptions& design = scenario->design;
  RequireInRange("gamma_power", static_cast<long>(FLAGS_gamma_power), -30, 30, "e.g. -1");
  RequireInRange("taubin_lambda", FLAGS_taubin_lambda, 1e-6, 1, "e.g. 0.5");
  RequireInRange("taubin_mu", FLAGS_taubin_mu, -1, -1e-6, "e.g. -0.53");
  RequireInRange("taubin_iterations", static_cast<long>(FLAGS_taubin_iterations), 1, 1000,
                 "e.g. 1");
  RequireInRange("target_penetration", FLAGS_target_penetration, 1e-6, 0.02,
                 "metres, e.g. 3e-4 (0.3 mm)");
  if (FLAGS_exponent < 2 || FLAGS_exponent > 4)
    throw InputError("--exponent", "", "must be 2, 3 or 4", "use --exponent=3 (the paper)");
  if (!(FLAGS_pressure_smoothing >= 0 && FLAGS_pressure_smoothing <= 1))
    throw InputError("--pressure_smoothing", "", "must lie in [0, 1]", "use 1 (the paper) or less");
  if (FLAGS_taubin_iterations < 1)
    throw InputError("--taubin_iterations", "", "must be at least 1", "e.g. 1");
  if (!ParseDesignPlacement(FLAGS_placement, &design.placement)) {
    throw InputError("--placement", "", "'" + FLAGS_placement + "' is unknown",
                     "use fresh, anchored or followed");
  }
  if (FLAGS_line_search != "golden" && FLAGS_line_search != "interpolated")
    throw InputError("--line_search", "", "'" + FLAGS_line_search + "' is unknown",
                     "use golden or interpolated");
  design.equilibrium.interpolated_line_search = FLAGS_line_search == "interpolated";
  RequireInRange("max_newton_iterations", static_cast<long>(FLAGS_max_newton_iterations), 1, 100000,
                 "e.g. 100");
  design.equilibrium.max_iterations = FLAGS_max_newton_iterations;
  design.equilibrium.contact_support_springs = FLAGS_support_springs;
  if (FLAGS_score_sides != "both" && FLAGS_score_sides != "skin")
    throw InputError("--score_sides", "", "'" + FLAGS_score_sides + "' is unknown",
                     "use both or skin");
  design.score_support_side = FLAGS_score_sides == "both";
  if (FLAGS_design_metric != "vertex" && FLAGS_design_metric != "l2")
    throw InputError("--design_metric", "", "'" + FLAGS_design_metric + "' is unknown",
                     "use vertex or l2");
  design.l2_design_metric = FLAGS_design_metric == "l2";
  design.pressure.exponent = FLAGS_exponent;
  design.pressure.smoothing = FLAGS_pressure_smoothing;
  design.taubin = {FLAGS_taubin_lambda, FLAGS_taubin_mu, FLAGS_taubin_iterations};

  if (FLAGS_contact_stiffness == "scenario") return;
  if (FLAGS_contact_stiffness != "auto") {
    const double k = ParseNonNegative(FLAGS_contact_stiffness, "contact_stiffness");
    RequireInRange("contact_stiffness", k, 1e3, 1e14,
                   "κ in Pa/m (contact pressure per metre of penetration), e.g. 1e8, or auto");
    design.equilibrium.contact_stiffness = k;
    return;
  }
  if (!(FLAGS_target_penetration > 0))
    throw InputError("--target_penetration", "", "must be positive", "e.g. 3e-4 (0.3 mm)");
  EquilibriumSolver solver(*scenario->body, design.equilibrium);
  EquilibriumResult last;
  const CalibrationResult calibration =
      CalibrateContactStiffness(solver, Support(scenario->support), scenario->start,
                                FLAGS_target_penetration, CalibrationOptions(), &last);
  std::cout << "  stiffness calibration: " << calibration.BriefReport() << "\n";
  design.equilibrium.contact_stiffness = solver.options().contact_stiffness;
}

double ApplyGammaFlags(DesignProblem* problem, const DesignEvaluation* at_x0) {
  double gamma = 0;
  if (FLAGS_gamma == "auto") {
    std::string message;
    gamma = at_x0 ? AutoGammaFrom(*at_x0, FLAGS_gamma_power, &message)
                  : AutoGamma(*problem, FLAGS_gamma_power, &message);
    if (gamma < 0) throw InputError("--gamma", "", message, "give --gamma=VALUE explicitly");
    std::cout << "  " << message << "\n";
  } else {
    gamma = ParseNonNegative(FLAGS_gamma, "gamma");
  }
  if (!std::isfinite(gamma) || gamma > 1e300) {
    throw InputError("--gamma_power", "",
                     "makes γ " + std::to_string(gamma) + ", which overflows φ",
                     "use a power between -20 and 20");
  }
  problem->set_gamma(gamma);
  return gamma;
}

}  // namespace ergo
