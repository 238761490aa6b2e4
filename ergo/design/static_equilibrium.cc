#include "ergo/design/static_equilibrium.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "ergo/design/equilibrium_report.h"
#include "ergo/equilibrium/calibrate_contact_stiffness.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/ergonomics/pressure_cost.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

using Clock = std::chrono::steady_clock;

void RequireOption(bool ok, const std::string& option, const std::string& what,
                   const std::string& fix) {
  if (!ok) throw InputError("--" + option, "", what, fix);
}

std::string Format(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char line[256];
  std::snprintf(line, sizeof line, format, a, b, c, d);
  return line;
}

}  // namespace

bool StaticEquilibrium::ok() const {
  return result.converged && (result.contact_vertices > 0 || result.contact_springs > 0) &&
         (!calibration || calibration->converged);
}

std::string StaticEquilibrium::message() const {
  if (out_of_time) return "stopped: --max_seconds ran out (" + result.message + ")";
  if (!result.converged) return result.message;
  if (result.contact_vertices == 0 && result.contact_springs == 0)
    return "the body does not touch the support at equilibrium";
  if (calibration && !calibration->converged)
    return "the stiffness calibration did not reach the target penetration: " +
           calibration->message;
  return "ok";
}

StaticEquilibrium SolveStaticEquilibrium(const LayeredBody& body, const TriMesh& support_mesh,
                                         const std::string& source,
                                         const StaticEquilibriumOptions& options) {
  RequireOption(options.contact_stiffness >= 0 && std::isfinite(options.contact_stiffness),
                "contact_stiffness", "must be a positive κ in Pa/m (or auto)", "e.g. 1e8");
  RequireOption(options.target_penetration >= 1e-6 && options.target_penetration <= 0.02,
                "target_penetration", "must be in [1e-6, 0.02] m", "e.g. 3e-4 (0.3 mm)");
  RequireOption(options.gap >= 0 && options.gap <= 0.1, "gap", "must be in [0, 0.1] m",
                "e.g. 0.001");
  RequireOption(options.max_seconds >= 0 && std::isfinite(options.max_seconds), "max_seconds",
                "must be >= 0 seconds", "0 = no limit");
  const auto begin = Clock::now();
  auto elapsed = [&] { return SecondsSince(begin); };
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(Format("%7.1f s  ", elapsed()) + line);
  };

  const Support support(support_mesh, source);
  if (options.soft_support &&
      (options.soft_support->boundary().surface.vertices.rows() != support_mesh.vertices.rows() ||
       options.soft_support->boundary().surface.triangles != support_mesh.triangles)) {
    throw InputError(source, "", "the soft support's boundary is not this support mesh",
                     "pass the soft part's boundary surface as the support");
  }
  StaticEquilibrium solved;
  // The stop flag the solver polls: the caller's, or the clock running out.
  std::atomic<bool> stop{false};
  auto should_stop = [&] {
    if (options.stop && options.stop->load()) return true;
    if (options.max_seconds > 0 && elapsed() > options.max_seconds) {
      solved.out_of_time = true;
      return true;
    }
    return false;
  };

  EquilibriumOptions equilibrium;
  equilibrium.relative_tolerance = options.relative_tolerance;
  equilibrium.max_iterations = options.max_iterations;
  equilibrium.stall_iterations = options.stall_iterations;
  equilibrium.contact_support_springs = options.two_way_contact;
  equilibrium.stop = &stop;
  equilibrium.progress = [&](const NewtonIterationReport& r) {
    say(Format("Newton %3.0f  residual %.3e N  step %.3g  contact vertices %.0f", r.iteration,
               r.residual, r.step, r.contact_vertices));
    if (should_stop()) stop = true;
  };
  const bool calibrate = options.contact_stiffness == 0;
  if (calibrate) {
    // A first guess from the load: spread over ~1 % of the skin (at least ten vertices'
    // areas) at the target depth.
    const Eigen::VectorXd& areas = body.skin().rest_areas;
    const double guess_area = std::max(10.0 * areas.mean(), 0.01 * areas.sum());
    equilibrium.contact_stiffness =
        body.TotalLoad().norm() / (guess_area * options.target_penetration);
  } else {
    equilibrium.contact_stiffness = options.contact_stiffness;
  }

  if (!options.start_rotation.allFinite())
    throw InputError("equilibrium options", "start_rotation", "is not finite",
                     "give a finite rotation vector, rad");
  BodyState start =
      options.start_rotation.isZero()
          ? RestState(body)
          : MovedRigidly(body, RestState(body), Eigen::Vector3d::Zero(), options.start_rotation);
  if (options.place) {
    const PlacementResult placed = PlaceAboveSupport(body, start, support, options.gap);
    solved.placed_found = placed.found;
    say(placed.found
            ? Format("placed %.2f mm along the load, %.2f mm above the support", 1e3 * placed.moved,
                     1e3 * options.gap)
            : "the body meets the support nowhere along the load; solving from where it is");
    start = placed.state;
  }

  EquilibriumSolver solver(body, equilibrium, options.soft_support);
  if (calibrate) {
    CalibrationOptions calibration_options;
    int step = 0;
    calibration_options.progress = [&](double k, double penetration) {
      say(Format("calibration %2.0f: κ %.4g Pa/m  max penetration %.4f mm", ++step, k,
                 1e3 * penetration));
    };
    EquilibriumResult last;
    solved.calibration = CalibrateContactStiffness(
        solver, support, start, options.target_penetration, calibration_options, &last);
    say("stiffness calibration: " + solved.calibration->BriefReport());
    // Final, reported solve at the calibrated κ from the last converged state.
    solved.result = solver.Solve(support, last.converged ? last.state : start);
  } else {
    solved.result = solver.Solve(support, start);
  }
  solved.contact_stiffness = solver.options().contact_stiffness;
  say("equilibrium: " + solved.result.BriefReport());

  // Pressures from the very springs of the final state (the solver's last evaluation).
  const ContactPressureEvaluator evaluator(body, support_mesh, PressureCostOptions());
  // A soft support's contact quadrature is over its rest areas (TotalPotential).
  solved.pressures = evaluator.Evaluate(solver.last_evaluation().contacts,
                                        solver.potential().ContactSurface(support).vertex_areas());
  solved.compression = MeasureTissueCompression(body, solved.result.state);
  solved.summary = EquilibriumSummary(body, solved.result, solved.pressures,
                                      solved.contact_stiffness, solved.compression);
  if (solved.calibration) {
    Json calibration = Json::object();
    calibration["converged"] = solved.calibration->converged;
    calibration["target_penetration_m"] = solved.calibration->target;
    calibration["penetration_m"] = solved.calibration->penetration;
    calibration["evaluations"] = solved.calibration->evaluations;
    calibration["message"] = solved.calibration->message;
    solved.summary["calibration"] = calibration;
  }
  solved.summary["lock"] = body.lock().ToString();
  solved.summary["contact"] =
      solved.result.contact_vertices > 0 || solved.result.contact_springs > 0;
  solved.summary["ok"] = solved.ok();
  solved.summary["message"] = solved.message();
  solved.summary["out_of_time"] = solved.out_of_time;
  if (options.soft_support) {
    const TotalPotential::Evaluation& e = solver.last_evaluation();
    const Vertices moved = e.support_positions - options.soft_support->rest().vertices;
    Json soft = Json::object();
    soft["vertices"] = static_cast<long long>(options.soft_support->rest().vertices.rows());
    soft["tets"] = static_cast<long long>(options.soft_support->rest().tets.rows());
    soft["max_displacement_m"] = moved.rows() > 0 ? moved.rowwise().norm().maxCoeff() : 0.0;
    solved.summary["soft_support"] = soft;
  }
  return solved;
}

}  // namespace ergo
