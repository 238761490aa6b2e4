// ergo_simulate: the static contact equilibrium of a body (a directory written by
// `ergo_body build`) resting on a support mesh under gravity and an external wrench (paper
// §3.3–3.5). Writes OUT/body_deformed.vtu, OUT/support.vtu, OUT/summary.json and the skin's
// pressure map (plot_data.json; pressure_map.png and pressure_histogram.png by
// tools/plot_simulation.py), as one unit (a killed run leaves the previous OUT or none). The work
// is SolveStaticEquilibrium (ergo/design/static_equilibrium.h); its progress (placement,
// calibration steps, Newton iterations, elapsed time) goes to stderr unless --progress=false.
// --load_point, --regions and --roll read the body along its length as ergo_optimize reads the
// shoe's foot (length_reading.h). Exit status: 0 converged with the stiffness asked for, 1 the
// computation did not succeed (not converged, no contact, stiffness calibration failed: the summary
// says why; or
// --max_seconds ran out: nothing written), 2 unusable input, 130 / 143 interrupted (nothing
// written).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/body/body_directory.h"
#include "ergo/body/core_lock.h"
#include "ergo/design/equilibrium_report.h"
#include "ergo/design/static_equilibrium.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_io.h"
#include "tools/common/child_process.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"
#include "tools/common/run_signals.h"
#include "tools/common/soft_support_flags.h"
#include "tools/common/vtu_flags.h"
#include "tools/ergo_simulate/length_reading.h"
#include "tools/ergo_simulate/plot_data.h"

DEFINE_string(body, "", "body directory written by `ergo_body build` (required)");
DEFINE_string(support, "",
              "support surface mesh: .obj .off .ply .stl .msh (required, closed; with "
              "--support_model=soft and --support_tets, optional)");
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
DEFINE_int32(stall_iterations, 5,
             "also accept a residual held below 1e-6 of the load (or --tolerance, if larger) for "
             "this many Newton iterations in a row, reported as 'converged (stalled)' (a faceted "
             "support's creases can keep Newton from --tolerance); 0 = only --tolerance");
DEFINE_int32(max_iterations, 100, "Newton iteration cap");
DEFINE_bool(support_springs, false,
            "two-way contact: the support's vertices inside the skin push too (always so with "
            "--support_model=soft); false: the paper's one-way equilibrium, the support's side "
            "scored only");
DEFINE_int32(threads, 0, "threads for assembly and contact (0 = all cores)");
DEFINE_bool(progress, true,
            "print progress to stderr: placement, each calibration step and Newton iteration "
            "(residual, contact vertices) with the elapsed time");
DEFINE_bool(plot, true,
            "write pressure_map.png and pressure_histogram.png with tools/plot_simulation.py "
            "(python3 + matplotlib; plot_data.json is written either way)");
DEFINE_double(max_seconds, 0,
              "stop when the job has run this long, seconds (exit 1, nothing written); 0 = no "
              "limit");

namespace ergo {
namespace {

namespace fs = std::filesystem;

void Require(const std::string& value, const std::string& flag) {
  if (value.empty()) throw InputError("--" + flag, "", "is required", "see ergo_simulate --help");
}

// The support's size against the body's: a file in millimetres read as metres is a thousand
// times too large (and the other way round).
void CheckUnits(const LayeredBody& body, const TriMesh& support) {
  const Vertices& b = body.rest().vertices;
  const double body_size = (b.colwise().maxCoeff() - b.colwise().minCoeff()).norm();
  const double support_size =
      (support.vertices.colwise().maxCoeff() - support.vertices.colwise().minCoeff()).norm();
  const double ratio = support_size / body_size;
  if (ratio > 100 || ratio < 1e-2) {
    std::ostringstream what;
    what << "the support is " << support_size << " m across and the body " << body_size
         << " m: the units disagree by about " << (ratio > 1 ? ratio : 1 / ratio) << "x";
    throw InputError(
        "--unit", "", what.str(),
        ratio > 1 ? "a file in millimetres needs --unit=mm" : "a file in metres needs --unit=m");
  }
}

int Run() {
  Require(FLAGS_body, "body");
  const bool soft = SoftSupportRequested();
  CheckSoftSupportFlags();
  if (!soft || SoftSupportTetFile().empty()) Require(FLAGS_support, "support");
  Require(FLAGS_out, "out");
  RequireInRange("max_iterations", static_cast<long>(FLAGS_max_iterations), 1, 100000, "e.g. 100");
  RequireInRange("gap", FLAGS_gap, 0, 0.1, "metres, e.g. 0.001");
  RequireInRange("target_penetration", FLAGS_target_penetration, 1e-6, 0.02,
                 "metres, e.g. 3e-4 (0.3 mm)");
  RequireInRange("tolerance", FLAGS_tolerance, 1e-14, 1e-2, "e.g. 1e-8");
  RequireInRange("stall_iterations", static_cast<long>(FLAGS_stall_iterations), 0, 1000,
                 "e.g. 5; 0 = only --tolerance");
  RequireInRange("threads", static_cast<long>(FLAGS_threads), 0, 1024, "0 = all cores");
  RequireInRange("max_seconds", FLAGS_max_seconds, 0, 1e7, "seconds, 0 = no limit");
  LengthUnit unit;
  if (!ParseLengthUnit(FLAGS_unit, &unit))
    throw InputError("--unit", "", "'" + FLAGS_unit + "' is not m or mm",
                     "use --unit=m or --unit=mm");
  if (FLAGS_place != "auto" && FLAGS_place != "none")
    throw InputError("--place", "", "'" + FLAGS_place + "'", "use auto or none");
  const VtuEncoding vtu_encoding = VtuEncodingFromFlags();
  LengthReading length_reading = ParseLengthFlags();
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);

  LayeredBodyOptions scenario;
  scenario.gravity = ParseThreeNumbers("gravity", FLAGS_gravity, "0,-9.81,0");
  scenario.external_force = ParseThreeNumbers("external_force", FLAGS_external_force, "0,-300,0");
  scenario.external_torque = ParseThreeNumbers("external_torque", FLAGS_external_torque, "0,0,1.5");
  scenario.lock = ParseCoreLock(FLAGS_lock, "--lock");
  if (scenario.gravity.norm() == 0 && scenario.external_force.norm() == 0) {
    throw InputError("--gravity", "",
                     "and --external_force are both zero: nothing presses the "
                     "body onto the support",
                     "give gravity (default 0,-9.81,0) or an external force");
  }
  StopOnSignals signals;
  OutputDirectory output(FLAGS_out, "--out");  // writable, checked before any work
  LayeredBody body = LoadLayeredBody(FLAGS_body, scenario);
  ResolveLengthReading(FLAGS_body, body, &length_reading);
  ApplyLoadPoint(length_reading, &body);
  TriMesh support_mesh =
      FLAGS_support.empty() ? TriMesh{} : ReadTriMesh(FLAGS_support, ReadOptions{unit});
  const std::string support_source = FLAGS_support.empty() ? SoftSupportTetFile() : FLAGS_support;
  std::shared_ptr<const ElasticPart> soft_support;
  if (soft) {
    TriMesh boundary;
    soft_support =
        SoftSupportFromFlags(support_mesh, FLAGS_support, unit, scenario.gravity, &boundary);
    support_mesh = std::move(boundary);  // the contact surface is the part's boundary
  }
  CheckUnits(body, support_mesh);

  StaticEquilibriumOptions options;
  options.relative_tolerance = FLAGS_tolerance;
  options.stall_iterations = FLAGS_stall_iterations;
  options.max_iterations = FLAGS_max_iterations;
  options.target_penetration = FLAGS_target_penetration;
  options.start_rotation = Eigen::Vector3d(0, 0, length_reading.roll);
  if (length_reading.stance) std::cout << length_reading.stance->BriefReport() << "\n";
  options.place = FLAGS_place == "auto";
  options.gap = FLAGS_gap;
  options.max_seconds = FLAGS_max_seconds;
  options.stop = &StopOnSignals::flag();
  options.soft_support = soft_support;
  options.two_way_contact = FLAGS_support_springs || soft;
  if (FLAGS_progress) {
    options.progress = [](const std::string& line) {
      std::cerr << line << "\n";
      std::cerr.flush();
    };
  }
  if (FLAGS_contact_stiffness != "auto") {
    char* end = nullptr;
    options.contact_stiffness = std::strtod(FLAGS_contact_stiffness.c_str(), &end);
    if (end == FLAGS_contact_stiffness.c_str() || *end != '\0' ||
        !(options.contact_stiffness > 0) || !std::isfinite(options.contact_stiffness)) {
      throw InputError("--contact_stiffness", "",
                       "'" + FLAGS_contact_stiffness + "' is neither a positive number nor auto",
                       "give κ in Pa/m (e.g. 1e8) or auto");
    }
  }
  const StaticEquilibrium solved =
      SolveStaticEquilibrium(body, support_mesh, support_source, options);
  const EquilibriumResult& result = solved.result;
  if (!solved.placed_found) {
    std::cerr << "warning: the body meets the support nowhere along the load direction; solved "
                 "from where it was\n";
  }
  if (solved.calibration)
    std::cout << "stiffness calibration: " << solved.calibration->BriefReport() << "\n";
  std::cout << result.FullReport() << "\n";
  const TissueCompression& compression = solved.compression;
  const std::string crushed = DescribeTissueCompression(compression);
  if (!crushed.empty()) std::cerr << "ergo_simulate: " << crushed << "\n";
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_simulate: interrupted before any result; nothing written\n";
    return StopOnSignals::ExitCode();
  }
  if (solved.out_of_time) {
    std::cerr << "ergo_simulate: --max_seconds=" << FLAGS_max_seconds
              << " ran out before the equilibrium converged; nothing written (raise "
                 "--max_seconds, or 0 for no limit)\n";
    return 1;
  }

  const fs::path out(output.path());
  WriteDeformedBodyVtu((out / "body_deformed.vtu").string(), body, result.state, solved.pressures,
                       vtu_encoding);
  if (soft_support) {
    // The deformed support: its surface (pressures, displacement from rest) and its solid.
    const Vertices positions = SoftSupportPositions(*soft_support, result.state);
    const TriMesh deformed = SoftSupportSurface(*soft_support, support_mesh, positions);
    WriteSupportVtu((out / "support.vtu").string(), deformed, solved.pressures,
                    support_mesh.vertices, vtu_encoding);
    WriteSoftSupportVtu((out / "support_solid.vtu").string(), *soft_support, positions,
                        vtu_encoding);
  } else {
    WriteSupportVtu((out / "support.vtu").string(), support_mesh, solved.pressures, Vertices(),
                    vtu_encoding);
  }
  Json summary = solved.summary;
  const std::string length_line =
      ReportLengthReading(length_reading, body, result.state, solved.pressures.contacts, &summary);
  if (!length_line.empty()) std::cout << length_line << "\n";
  std::cout << "peak skin pressure " << summary["peak_pressure_Pa"].get<double>() / 1e3 << " kPa";
  if (summary.contains("plate_peak")) {
    std::cout << "; a 5 mm pressure plate under the skin would read "
              << summary["plate_peak"]["pressure_Pa"].get<double>() / 1e3
              << " kPa at its largest cell";
  }
  std::cout << "\n";
  summary["body_directory"] = FLAGS_body;
  summary["support_file"] = support_source;
  summary["support_model"] = DescribeSoftSupportFlags();
  const bool touched = result.contact_vertices > 0 || result.contact_springs > 0;
  const bool calibrated = !solved.calibration || solved.calibration->converged;
  WriteJsonFile((out / "summary.json").string(), summary);
  WriteJsonFile(
      (out / "plot_data.json").string(),
      SimulationPlotData(body, result.state, solved.pressures, compression, length_reading, summary,
                         fs::path(FLAGS_body).filename().string() + " on " +
                             fs::path(support_source).filename().string()));
  const bool plotted = FLAGS_plot && !StopOnSignals::stopped() &&
                       RunPictureScript("ergo_simulate", "plot_simulation.py", output.path());
  std::string error;
  if (!output.Commit(&error)) {
    std::cerr << "ergo_simulate: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << output.final_path() << "/body_deformed.vtu, support.vtu, "
            << (soft_support ? "support_solid.vtu, " : "") << "summary.json, plot_data.json"
            << (plotted ? ", pressure_map.png, pressure_histogram.png" : "") << "\n";
  if (!result.converged) {
    // Said last, where a reader of the figures above looks: they are the last iterate's.
    std::cout.flush();
    std::cerr << "ergo_simulate: the equilibrium did not converge (" << result.message
              << "): the files hold the last iterate for inspection, and the split, peaks and "
                 "pressures printed above are not an equilibrium's (raise --max_iterations or "
                 "--max_seconds; tissue crushed past its law, when warned of above, often keeps "
                 "Newton from converging)\n";
    return 1;
  }
  if (!touched) {
    std::cerr << "ergo_simulate: the body does not touch the support at equilibrium\n";
    return 1;
  }
  if (!calibrated) {
    std::cerr << "ergo_simulate: the stiffness calibration did not reach --target_penetration "
                 "(the summary's calibration says why); the result uses the last stiffness\n";
    return 1;
  }
  return 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "static contact equilibrium of a body on a support\n"
      "  ergo_simulate --body=DIR --support=FILE [--unit=mm] [--external_force=FX,FY,FZ]\n"
      "    [--external_torque=TX,TY,TZ] [--load_point=F [--heel_end=min_z|max_z]]\n"
      "    [--regions=auto|foot|none] [--roll=DEG|stance [--calcaneal_stance=DEG]]\n"
      "    [--lock=tx,tz,...] [--contact_stiffness=KAPPA|auto]\n"
      "    [--support_model=soft [--support_youngs_modulus=PA] [--support_tets=FILE]] --out=OUT");
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_simulate: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_simulate: " << error.what() << "\n";
    return 2;
  }
}
