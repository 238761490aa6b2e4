// ergo_simulate: the static contact equilibrium of a body (a directory written by
// `ergo_body build`) resting on a support mesh under gravity and an external wrench (paper
// §3.3–3.5). Writes OUT/body_deformed.vtu, OUT/support.vtu and OUT/summary.json.
// Exit status: 0 converged, 1 not converged (the summary says why), 2 unusable input.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/body/body_directory.h"
#include "ergo/body/core_lock.h"
#include "ergo/design/contact_pressures.h"
#include "ergo/design/equilibrium_report.h"
#include "ergo/equilibrium/calibrate_contact_stiffness.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_io.h"

DEFINE_string(body, "", "body directory written by `ergo_body build` (required)");
DEFINE_string(support, "", "support surface mesh: .obj .off .ply .stl .msh (required, closed)");
DEFINE_string(unit, "m", "unit of the support file's coordinates: m or mm");
DEFINE_string(out, "", "output directory (required; created if missing)");
DEFINE_string(external_force, "0,0,0", "force on the core FX,FY,FZ in N");
DEFINE_string(external_torque, "0,0,0", "torque on the core about its centre TX,TY,TZ in N·m");
DEFINE_string(gravity, "0,-9.81,0", "gravity vector in m/s² (the paper's convention is −y)");
DEFINE_string(lock, "tx,tz", "core DOFs to lock: any of tx,ty,tz,rx,ry,rz (or none)");
DEFINE_string(contact_stiffness, "auto",
              "contact stiffness κ in Pa/m (contact pressure per metre of penetration: a vertex's "
              "spring is κ times its area), or auto (calibrated to --target_penetration)");
DEFINE_double(target_penetration, 3e-4, "max penetration the auto stiffness aims at, m");
DEFINE_string(place, "auto", "auto: move the body along the load to --gap above the support; none");
DEFINE_double(gap, 1e-3, "gap left by --place=auto, m");
DEFINE_double(tolerance, 1e-8, "convergence: force residual relative to the load");
DEFINE_int32(max_iterations, 100, "Newton iteration cap");
DEFINE_int32(threads, 0, "threads for assembly and contact (0 = all cores)");

namespace ergo {
namespace {

Eigen::Vector3d ParseVector(const std::string& text, const std::string& flag) {
  std::stringstream stream(text);
  Eigen::Vector3d v;
  std::string item;
  int k = 0;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (k >= 3 || end == item.c_str() || *end != '\0' || !std::isfinite(value)) {
      throw InputError("--" + flag, "", "'" + text + "' is not three finite numbers",
                       "write X,Y,Z, e.g. 0,-300,0");
    }
    v[k++] = value;
  }
  if (k != 3)
    throw InputError("--" + flag, "", "'" + text + "' is not three numbers",
                     "write X,Y,Z, e.g. 0,-300,0");
  return v;
}

void Require(const std::string& value, const std::string& flag) {
  if (value.empty()) throw InputError("--" + flag, "", "is required", "see ergo_simulate --help");
}

int Run() {
  Require(FLAGS_body, "body");
  Require(FLAGS_support, "support");
  Require(FLAGS_out, "out");
  LengthUnit unit;
  if (!ParseLengthUnit(FLAGS_unit, &unit))
    throw InputError("--unit", "", "'" + FLAGS_unit + "' is not m or mm",
                     "use --unit=m or --unit=mm");
  if (FLAGS_place != "auto" && FLAGS_place != "none")
    throw InputError("--place", "", "'" + FLAGS_place + "'", "use auto or none");
  if (!(FLAGS_tolerance > 0)) throw InputError("--tolerance", "", "must be positive", "e.g. 1e-8");
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);

  LayeredBodyOptions scenario;
  scenario.gravity = ParseVector(FLAGS_gravity, "gravity");
  scenario.external_force = ParseVector(FLAGS_external_force, "external_force");
  scenario.external_torque = ParseVector(FLAGS_external_torque, "external_torque");
  scenario.lock = ParseCoreLock(FLAGS_lock, "--lock");
  const LayeredBody body = LoadLayeredBody(FLAGS_body, scenario);
  const TriMesh support_mesh = ReadTriMesh(FLAGS_support, ReadOptions{unit});
  const Support support(support_mesh, FLAGS_support);

  const bool auto_stiffness = FLAGS_contact_stiffness == "auto";
  EquilibriumOptions options;
  options.relative_tolerance = FLAGS_tolerance;
  options.max_iterations = FLAGS_max_iterations;
  if (auto_stiffness) {
    // A first guess from the load: spread over ~1 % of the skin (at least ten vertices'
    // areas) at the target depth.
    const Eigen::VectorXd& areas = body.skin().rest_areas;
    const double guess_area = std::max(10.0 * areas.mean(), 0.01 * areas.sum());
    options.contact_stiffness =
        body.TotalLoad().norm() / (guess_area * FLAGS_target_penetration);
  } else {
    char* end = nullptr;
    options.contact_stiffness = std::strtod(FLAGS_contact_stiffness.c_str(), &end);
    if (end == FLAGS_contact_stiffness.c_str() || *end != '\0' ||
        !(options.contact_stiffness > 0) || !std::isfinite(options.contact_stiffness)) {
      throw InputError("--contact_stiffness", "",
                       "'" + FLAGS_contact_stiffness + "' is neither a positive number nor auto",
                       "give κ in Pa/m (e.g. 1e8) or auto");
    }
  }

  BodyState start = RestState(body);
  if (FLAGS_place == "auto") {
    const PlacementResult placed = PlaceAboveSupport(body, start, support, FLAGS_gap);
    if (!placed.found) {
      std::cerr << "warning: the body meets the support nowhere along the load direction; solving "
                   "from where it is\n";
    }
    start = placed.state;
  }

  EquilibriumSolver solver(body, options);
  Json calibration_json;
  EquilibriumResult result;
  if (auto_stiffness) {
    const CalibrationResult calibration = CalibrateContactStiffness(
        solver, support, start, FLAGS_target_penetration, CalibrationOptions(), &result);
    std::cout << "stiffness calibration: " << calibration.BriefReport() << "\n";
    calibration_json = Json::Object();
    calibration_json["converged"] = calibration.converged;
    calibration_json["target_penetration_m"] = calibration.target;
    calibration_json["penetration_m"] = calibration.penetration;
    calibration_json["evaluations"] = calibration.evaluations;
    calibration_json["message"] = calibration.message;
    // Final, reported solve at the calibrated k from the last converged state.
    result = solver.Solve(support, result.converged ? result.state : start);
  } else {
    result = solver.Solve(support, start);
  }
  std::cout << result.FullReport() << "\n";

  // Pressures from the very springs of the final state (the solver's last evaluation).
  const ContactPressureEvaluator evaluator(body, support_mesh, PressureCostOptions());
  const ContactPressures pressures =
      evaluator.Evaluate(solver.last_evaluation().contacts, support.vertex_areas());

  std::filesystem::create_directories(FLAGS_out);
  const std::filesystem::path out(FLAGS_out);
  WriteDeformedBodyVtu((out / "body_deformed.vtu").string(), body, result.state, pressures);
  WriteSupportVtu((out / "support.vtu").string(), support_mesh, pressures, Vertices());
  Json summary = EquilibriumSummary(body, result, pressures, solver.options().contact_stiffness);
  if (!calibration_json.is_null()) summary["calibration"] = calibration_json;
  summary["body_directory"] = FLAGS_body;
  summary["support_file"] = FLAGS_support;
  summary["lock"] = body.lock().ToString();
  WriteJsonFile((out / "summary.json").string(), summary);
  std::cout << "wrote " << (out / "body_deformed.vtu").string() << ", support.vtu, summary.json\n";
  return result.converged ? 0 : 1;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "static contact equilibrium of a body on a support\n"
      "  ergo_simulate --body=DIR --support=FILE [--unit=mm] [--external_force=FX,FY,FZ]\n"
      "    [--external_torque=TX,TY,TZ] [--lock=tx,tz,...] [--contact_stiffness=KAPPA|auto] --out=OUT");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_simulate: " << error.what() << "\n";
    return 2;
  }
}
