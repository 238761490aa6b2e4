// ergo_optimize: the designer's main job (paper §4–5). Takes a scenario (chair, shoe sole,
// mouse, …: --flagfile=data/SCENARIO.flags, any flag overridable), optimises the support's
// shape for even contact pressure with the chosen optimiser and budget, and writes to
// --out (default ./ergo_out): summary.md / summary.json (the paper's Table 1 columns),
// history.csv, the initial and optimised support as PLY and print-ready STL (mm), body and
// support VTU with pressure and displacement fields, and PNG pictures. Ctrl-C stops cleanly
// and writes everything for the best design so far. With no flags: the quick shoe sole.
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <Eigen/Geometry>
#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/design/placement_checks.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/laplacian.h"
#include "solvers/design_objective.h"
#include "solvers/history_csv.h"
#include "solvers/optimizer.h"
#include "tools/common/child_process.h"
#include "tools/common/design_flags.h"
#include "tools/common/scenario_flags.h"
#include "tools/ergo_optimize/run_outputs.h"

#ifndef ERGO_TOOLS_DIR
#define ERGO_TOOLS_DIR ""
#endif

DEFINE_string(
    optimizer, "paper-ncg",
    "optimiser: paper-ncg, steepest, ceres-lbfgs, ceres-ncg, nlopt-mma, nlopt-ccsaq, nlopt-lbfgs");
DEFINE_int32(max_evals, 100, "budget: φ evaluations (equilibrium solves), probes included");
DEFINE_double(max_seconds, 0, "budget: wall seconds; 0 = unlimited");
DEFINE_string(out, "ergo_out", "output directory (created if missing)");
DEFINE_int32(post_smoothing, 0,
             "Taubin iterations applied to the optimised design's designed region (paper §5.1; "
             "chair: a few)");
DEFINE_int32(threads, 0,
             "threads for assembly, contact and the probes' equilibria (0 = all cores)");
DEFINE_bool(plot, true, "write PNG pictures with tools/plot_results.py (python3 + matplotlib)");
DEFINE_bool(progress, true, "print one line per iteration");
DEFINE_double(placement_shift_mm, 3,
              "placement checks: the body lands this far off along each horizontal axis, mm");
DEFINE_double(placement_tilt_deg, 1,
              "placement checks: and tilted by this much about each free rotation axis, degrees");

namespace ergo {
namespace {

std::atomic<bool> g_stop{false};

void OnInterrupt(int) {
  g_stop = true;
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C kills
}

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

// The designed region smoothed by Taubin steps (non-designed vertices fixed), as the design
// closest to it (exact for positions; the normal kinds keep the normal part of the smoothing).
Eigen::VectorXd PostSmooth(const DesignProblem& problem, const Eigen::VectorXd& x, int iterations) {
  const TriMesh support = problem.SupportAt(x);
  const Eigen::VectorXi& active = problem.parameterization().active_vertices();
  std::vector<bool> fixed(static_cast<size_t>(support.vertices.rows()), true);
  for (Eigen::Index i = 0; i < active.size(); ++i) fixed[active[i]] = false;
  const TriMesh smoothed = TaubinSmooth(support, {0.5, -0.53, iterations}, fixed);
  return problem.parameterization().DesignFor(smoothed.vertices);
}

Json SummaryJson(const Scenario& scenario, const DesignReport& initial,
                 const DesignReport& optimized, const OptimizerResult& result, double gamma,
                 double wall, double stiffness) {
  Json s = Json::Object();
  s["scenario"] = scenario.name;
  s["description"] = scenario.description;
  s["optimizer"] = result.optimizer;
  s["initial_score"] = initial.evaluation.phi;
  s["optimized_score"] = optimized.evaluation.phi;
  s["reduction_percent"] = 100.0 * (1.0 - optimized.evaluation.phi / initial.evaluation.phi);
  s["initial_zeta"] = initial.evaluation.zeta;
  s["initial_skin_zeta"] = initial.evaluation.zeta_human;
  s["initial_support_zeta"] = initial.evaluation.zeta_support;
  s["optimized_zeta"] = optimized.evaluation.zeta;
  s["gamma"] = gamma;
  s["wall_s"] = wall;
  s["body_vertices"] = static_cast<long>(scenario.body->rest().vertices.rows());
  s["support_vertices"] = static_cast<long>(scenario.support.vertices.rows());
  s["contact_vertices"] = optimized.evaluation.equilibrium.contact_vertices;
  s["initial_contact_vertices"] = initial.evaluation.equilibrium.contact_vertices;
  s["initial_max_penetration_m"] = initial.evaluation.equilibrium.max_penetration;
  s["optimized_max_penetration_m"] = optimized.evaluation.equilibrium.max_penetration;
  s["initial_peak_pressure_Pa"] = initial.peak_pressure;
  s["optimized_peak_pressure_Pa"] = optimized.peak_pressure;
  s["contact_stiffness"] = stiffness;
  s["evaluations"] = result.evaluations;
  s["failed_evaluations"] = result.failed_evaluations;
  s["newton_iterations"] = result.newton_iterations;
  s["stop_reason"] = result.stop_reason;
  s["load_N"] = scenario.body->TotalLoad().norm();
  return s;
}

// The fresh-placement check in one sentence.
std::string FreshPlacementLine(const Json& s) {
  if (!s.Find("fresh_placement_converged")->AsBool()) {
    return "The body placed afresh on the optimised design did not reach equilibrium.\n\n";
  }
  return "The body placed afresh on the optimised design (from the start pose) settles with "
         "φ " +
         Format("%.4g", s.Find("fresh_placement_score")->AsNumber()) + " (" +
         Format("%.1f", s.Find("fresh_placement_reduction_percent")->AsNumber()) +
         " % below the initial φ); the figures above are the equilibrium the optimiser "
         "followed.\n\n";
}

std::string SummaryMarkdown(const Json& s) {
  auto number = [&](const char* key, const char* format) {
    return Format(format, s.Find(key)->AsNumber());
  };
  std::ostringstream md;
  md << "# ergo_optimize: " << s.Find("scenario")->AsString() << "\n\n"
     << s.Find("description")->AsString() << "\n\n"
     << "| | initial | optimised |\n|---|---|---|\n"
     << "| score φ | " << number("initial_score", "%.4g") << " | "
     << number("optimized_score", "%.4g") << " |\n"
     << "| ζ (pressure term) | " << number("initial_zeta", "%.4g") << " | "
     << number("optimized_zeta", "%.4g") << " |\n"
     << "| peak pressure (kPa) | "
     << Format("%.2f", s.Find("initial_peak_pressure_Pa")->AsNumber() / 1e3) << " | "
     << Format("%.2f", s.Find("optimized_peak_pressure_Pa")->AsNumber() / 1e3) << " |\n"
     << "| max penetration (mm) | "
     << Format("%.3f", s.Find("initial_max_penetration_m")->AsNumber() * 1e3) << " | "
     << Format("%.3f", s.Find("optimized_max_penetration_m")->AsNumber() * 1e3) << " |\n"
     << "| contact vertices | " << number("initial_contact_vertices", "%.0f") << " | "
     << number("contact_vertices", "%.0f") << " |\n\n"
     << "Table 1 columns: reduction " << number("reduction_percent", "%.1f")
     << " %, smoothing strength γ " << number("gamma", "%.3g") << ", time "
     << number("wall_s", "%.1f") << " s, " << number("body_vertices", "%.0f") << " body vertices, "
     << number("support_vertices", "%.0f") << " support vertices, "
     << number("contact_vertices", "%.0f") << " contact vertices.\n\n"
     << FreshPlacementLine(s) << "Optimiser " << s.Find("optimizer")->AsString() << ": "
     << number("evaluations", "%.0f") << " evaluations (" << number("failed_evaluations", "%.0f")
     << " failed), " << number("newton_iterations", "%.0f")
     << " Newton iterations; stopped: " << s.Find("stop_reason")->AsString() << ".\n\n"
     << "Files: support_initial/optimized.{ply,stl} (millimetres; the STL is closed and "
        "print-ready), "
        "body_*.vtu and support_*.vtu (pressure_Pa, contact_force_N, displacement_m), history.csv, "
        "pressure_maps.png, pressure_histograms.png, displacement.png, phi_history.png.\n";
  return md.str();
}

int Run() {
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  if (FLAGS_max_evals < 1)
    throw InputError("--max_evals", "", "must be at least 1", "e.g. --max_evals=100");
  Scenario scenario = ScenarioFromFlags();
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer(FLAGS_optimizer, OptimizerOptions(), &error);
  if (!optimizer)
    throw InputError("--optimizer", "", "'" + FLAGS_optimizer + "' is unknown", error);
  std::cout << "scenario " << scenario.name << ": " << scenario.description << "\n";

  const auto begin = std::chrono::steady_clock::now();
  ApplyDesignFlags(&scenario);  // exponent, smoothing, Taubin, contact stiffness
  const DesignOptions& design = scenario.design;
  DesignProblem problem = scenario.MakeProblem();
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const double gamma = ApplyGammaFlags(&problem);
  const DesignReport initial = ReportDesign(problem, x0);
  if (!initial.evaluation.ok) {
    std::cerr << "ergo_optimize: the initial equilibrium failed: " << initial.evaluation.message
              << "\n";
    return 1;
  }
  std::cout << "  initial φ " << initial.evaluation.phi << " (ζ " << initial.evaluation.zeta
            << ", γψ " << gamma * initial.evaluation.psi << "), "
            << initial.evaluation.equilibrium.contact_vertices << " contact vertices, peak "
            << initial.peak_pressure / 1e3 << " kPa, max penetration "
            << initial.evaluation.equilibrium.max_penetration * 1e3 << " mm\n";

  // The optimisation.
  Budget budget;
  budget.max_evaluations = FLAGS_max_evals;
  budget.max_seconds = FLAGS_max_seconds;
  RunControl control;
  control.stop = &g_stop;
  const double phi0 = initial.evaluation.phi;
  double best = phi0;
  control.progress = [&](const IterationRecord& r) {
    best = std::min(best, r.phi);
    if (FLAGS_progress) {
      const double per_eval =
          r.evaluations > 0 ? r.seconds / static_cast<double>(r.evaluations) : 0;
      double eta = per_eval * static_cast<double>(
                                  std::max(0L, static_cast<long>(FLAGS_max_evals) - r.evaluations));
      if (FLAGS_max_seconds > 0) eta = std::min(eta, std::max(0.0, FLAGS_max_seconds - r.seconds));
      std::printf("iter %4d  φ/φ₀ %.4f  best %.4f  evals %4ld  elapsed %6.1f s  ETA %6.1f s\n",
                  r.iteration, r.phi / phi0, best / phi0, r.evaluations, r.seconds, eta);
      std::fflush(stdout);
    }
    return true;
  };
  std::signal(SIGINT, OnInterrupt);
  DesignObjective objective(problem);
  OptimizerResult result = optimizer->Minimize(objective, x0, budget, control);
  std::signal(SIGINT, SIG_DFL);
  std::cout << result.BriefReport() << "\n";
  Eigen::VectorXd best_x = result.ok ? result.best_x : x0;

  // The best design on the problem that evaluated it: its warm-start cache holds the
  // equilibrium the optimiser saw there, so the report reproduces the φ it logged.
  DesignProblem* best_problem = &problem;
  if (result.ok && result.best_objective)
    best_problem = &static_cast<DesignObjective&>(*result.best_objective).problem();
  DesignReport optimized = ReportDesign(*best_problem, best_x);
  if (FLAGS_post_smoothing > 0 && optimized.evaluation.ok) {
    const Eigen::VectorXd smoothed_x = PostSmooth(problem, best_x, FLAGS_post_smoothing);
    DesignReport smoothed = ReportDesign(*best_problem, smoothed_x);
    std::cout << "post-smoothing (" << FLAGS_post_smoothing << " Taubin iterations): φ "
              << optimized.evaluation.phi << " -> "
              << (smoothed.evaluation.ok ? smoothed.evaluation.phi : NAN)
              << (smoothed.evaluation.ok && smoothed.evaluation.phi < optimized.evaluation.phi
                      ? " (kept)"
                      : " (discarded)")
              << "\n";
    if (smoothed.evaluation.ok && smoothed.evaluation.phi < optimized.evaluation.phi)
      optimized = std::move(smoothed);
  }
  if (!optimized.evaluation.ok) optimized = initial;  // nothing better was found that converged
  // The same design with the body placed on it afresh (from the scenario's start, as a user
  // would stand on the printed part). Contact with a sculpted support can have several
  // equilibria; the optimiser followed one continuously, a fresh placement may find another.
  DesignProblem fresh = scenario.MakeProblem();
  fresh.set_gamma(gamma);
  const DesignEvaluation placed = fresh.Evaluate(optimized.x, false);
  if (placed.ok) {
    std::cout << "fresh placement on the optimised design: φ/φ₀ " << placed.phi / phi0
              << " (optimiser's equilibrium " << optimized.evaluation.phi / phi0 << ")\n";
  } else {
    std::cout << "fresh placement on the optimised design failed: " << placed.message << "\n";
  }
  // Placement checks: the body landing 3 mm off along each horizontal axis, or tilted 1°.
  Json checks = Json::Array();
  for (const Placement& placement :
       PlacementChecks(*scenario.body, 1e-3 * FLAGS_placement_shift_mm,
                       FLAGS_placement_tilt_deg * M_PI / 180, /*with_tilts=*/true)) {
    DesignProblem at_initial = PlacedProblem(fresh, placement);
    DesignProblem at_optimized = PlacedProblem(fresh, placement);
    const DesignEvaluation a = at_initial.Evaluate(x0, false);
    const DesignEvaluation b = at_optimized.Evaluate(optimized.x, false);
    std::cout << "placement " << placement.name << ": initial φ/φ₀ " << (a.ok ? a.phi / phi0 : NAN)
              << ", optimised " << (b.ok ? b.phi / phi0 : NAN) << " (reduction "
              << (a.ok && b.ok ? 100 * (1 - b.phi / a.phi) : NAN) << " %)\n";
    Json c = Json::Object();
    c["name"] = placement.name;
    c["initial_score"] = a.ok ? a.phi : NAN;
    c["score"] = b.ok ? b.phi : NAN;
    checks.Append(c);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();

  // Outputs.
  std::filesystem::create_directories(FLAGS_out);
  const std::filesystem::path out(FLAGS_out);
  WriteDesignFiles(FLAGS_out, "initial", *scenario.body, initial, scenario.support.vertices);
  WriteDesignFiles(FLAGS_out, "optimized", *scenario.body, optimized, scenario.support.vertices);
  WriteHistoryCsv((out / "history.csv").string(), result);
  Json summary = SummaryJson(scenario, initial, optimized, result, gamma, wall,
                             design.equilibrium.contact_stiffness);
  summary["fresh_placement_converged"] = placed.ok;
  summary["placement_checks"] = checks;
  auto pose = [](const BodyState& state) {
    Json p = Json::Array();
    for (int k = 0; k < 3; ++k) p.Append(state.centre[k]);
    const Eigen::AngleAxisd angle(state.rotation);
    for (int k = 0; k < 3; ++k) p.Append(angle.angle() * angle.axis()[k]);
    return p;
  };
  summary["followed_core_pose"] = pose(optimized.evaluation.equilibrium.state);
  if (placed.ok) {
    summary["fresh_core_pose"] = pose(placed.equilibrium.state);
    summary["fresh_placement_score"] = placed.phi;
    summary["fresh_placement_reduction_percent"] = 100.0 * (1.0 - placed.phi / phi0);
  }
  WriteJsonFile((out / "summary.json").string(), summary);
  const std::string markdown = SummaryMarkdown(summary);
  WriteFileAtomically((out / "summary.md").string(),
                      [&](std::ostream& stream) { stream << markdown; });
  WriteJsonFile((out / "plot_data.json").string(), PlotData(scenario, initial, optimized), 0);
  if (FLAGS_plot) {
    // An argument vector, never a shell: --out may hold any character.
    const std::string python = FindPythonWithMatplotlib();
    if (python.empty()) {
      std::cerr << "warning: pictures not written: no python3 with matplotlib found (Debian: "
                   "apt-get install python3-matplotlib)\n";
    } else {
      const std::vector<std::string> command = {
          python, std::string(ERGO_TOOLS_DIR) + "/plot_results.py", FLAGS_out};
      const ChildProcessResult plotted = RunChildProcess(command);
      if (!plotted.ok())
        std::cerr << "warning: pictures not written: " << CommandLineForDisplay(command) << " "
                  << plotted.Describe() << "\n";
    }
  }
  std::cout << markdown << "wrote " << FLAGS_out << "/\n";
  return 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetCommandLineOptionWithMode("scenario", "shoe", gflags::SET_FLAGS_DEFAULT);
  gflags::SetUsageMessage(
      "optimise a support's shape for even contact pressure\n"
      "  ergo_optimize [--flagfile=data/SCENARIO.flags] [--optimizer=NAME] [--max_evals=N] "
      "[--max_seconds=S] [--out=DIR]");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_optimize: " << error.what() << "\n";
    return 2;
  }
}
