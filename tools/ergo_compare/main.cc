// ergo_compare: runs several outer optimisers (solvers/, paper §4.1) on one design scenario
// with the same budget — each on a fresh problem, so no warm-start state leaks between
// them — and compares which gets the most comfortable support soonest.
//
//   ergo_compare --scenario=bump --optimizers=paper-ncg,ceres-lbfgs,nlopt-mma
//       --max_evals=200 [--max_seconds=S] --out=DIR
//   ergo_compare --flagfile=data/chair.flags --optimizers=... --max_evals=200 --out=DIR
//
// Every optimiser runs in the same fresh rounds as ergo_optimize (solvers/fresh_rounds.h):
// the design each keeps is the one that scores best with the body placed afresh, and the
// table ranks them by that fresh reduction (the optimiser's own value on its path beside it).
// Writes DIR/compare.csv, DIR/<optimizer>_history.csv and DIR/compare.png (the kept design's
// φ/φ₀ placed afresh against seconds, the followed path's φ/φ₀ against evaluations; by
// tools/plot_compare.py, skipped with a warning when python3 or matplotlib is missing) and
// prints the table; DIR appears as a whole. Ctrl-C or
// SIGTERM stops the running optimiser cleanly with its best design so far and skips the rest.
//
// Exit status: 0 success, 1 an optimiser crashed, 2 bad input (flags, scenario),
// 130 / 143 interrupted (outputs are still written).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/design/placement_checks.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/split_list.h"
#include "solvers/design_objective.h"
#include "solvers/fresh_rounds.h"
#include "solvers/history_csv.h"
#include "solvers/optimizer.h"
#include "solvers/robust_design_objective.h"
#include "tools/common/child_process.h"
#include "tools/common/design_flags.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"
#include "tools/common/run_signals.h"
#include "tools/common/scenario_flags.h"

DEFINE_string(
    optimizers,
    "paper-ncg,ceres-lbfgs,ceres-ncg,nlopt-mma,nlopt-ccsaq,nlopt-lbfgs,nlopt-tnewton,steepest",
    "comma-separated optimisers to compare");
DEFINE_int32(max_evals, 200, "evaluation budget per optimiser (every φ evaluation counts)");
DEFINE_double(max_seconds, 0, "wall-clock budget per optimiser, s; 0 = unlimited");
DEFINE_double(gradient_tolerance, 1e-8,
              "stop when ||grad phi||_inf * 1 mm / |phi(x0)| falls below this");
DEFINE_double(function_tolerance, 1e-10,
              "stop when an iteration lowers phi by less than this fraction");
DEFINE_double(parameter_tolerance, 1e-8,
              "stop when an iteration moves no vertex more than this, mm");
DEFINE_string(probe_moves_mm, "0.001,0.01,0.1,0.2,0.5,0.7,1,2",
              "paper-ncg/steepest: largest vertex move of each trial step, mm (paper §4.1)");
DEFINE_int32(probe_threads, 0, "paper-ncg/steepest: probe threads; 0 = one per probe");
DEFINE_int32(restart_every, 0, "paper-ncg: restart with -grad every N iterations; 0 = #parameters");
DEFINE_double(total_move_mm, 20, "nlopt-*: no vertex moves farther than this from the start, mm");
DEFINE_double(round_move_mm, 2,
              "nlopt-*: no vertex moves farther than this within one round (the per-iteration "
              "cap; the box is re-centred on the best design after each round), mm; 0 = none");
DEFINE_int32(round_evaluations, 10, "nlopt-*: evaluations per round");
DEFINE_int32(lbfgs_rank, 20, "ceres-lbfgs: L-BFGS memory");
DEFINE_double(target_reduction, 70, "the table reports when each optimiser first reached this %");
DEFINE_int32(round_evals, 40,
             "evaluations per round before the best designs are placed afresh (as ergo_optimize); "
             "0 = one round");
DEFINE_int32(candidates, 3, "designs of each round placed afresh before one is kept");
DEFINE_string(out, "", "output directory (required; created if missing)");
DEFINE_bool(progress, true, "print one line per optimiser iteration");
DEFINE_bool(plot, true, "write compare.png with tools/plot_compare.py (python3 + matplotlib)");
DEFINE_string(python, "", "Python for the plot; default: python3, else /usr/bin/python3");
DEFINE_string(plot_script, "", "plot script; default: plot_compare.py in the source tools/ dir");

namespace ergo {
namespace {

constexpr char kUsage[] =
    "compares outer optimisers on one design scenario with the same budget.\n"
    "  ergo_compare [--flagfile=data/SCENARIO.flags | --scenario=bump [--bump_height=...]]\n"
    "      "
    "--optimizers=paper-ncg,ceres-lbfgs,ceres-ncg,nlopt-mma,nlopt-ccsaq,nlopt-lbfgs,nlopt-tnewton,"
    "steepest\n"
    "      --max_evals=N [--max_seconds=S] --out=DIR";

[[noreturn]] void FlagError(const std::string& flag, const std::string& what,
                            const std::string& fix) {
  throw InputError("--" + flag, "", what, fix);
}

// The comma-separated items of a flag, empty ones skipped.
std::vector<std::string> NonEmptyItems(const std::string& text) {
  std::vector<std::string> items = SplitList(text, ',');
  items.erase(std::remove(items.begin(), items.end(), std::string()), items.end());
  return items;
}

OptimizerOptions OptionsFromFlags() {
  OptimizerOptions options;
  options.probes.moves.clear();
  for (const std::string& item : NonEmptyItems(FLAGS_probe_moves_mm)) {
    double value = 0;
    try {
      size_t used = 0;
      value = std::stod(item, &used);
      if (used != item.size()) value = -1;
    } catch (const std::exception&) {
      value = -1;
    }
    if (!(value > 0)) {
      FlagError("probe_moves_mm", "expected positive lengths in mm, got \"" + item + "\"",
                "e.g. --probe_moves_mm=0.001,0.01,0.1,0.2,0.5,0.7,1,2");
    }
    options.probes.moves.push_back(1e-3 * value);
  }
  if (options.probes.moves.empty()) FlagError("probe_moves_mm", "is empty", "give the moves");
  if (FLAGS_probe_threads < 0) FlagError("probe_threads", "must be >= 0", "0 = one per probe");
  options.probes.threads = FLAGS_probe_threads;
  options.probes.restart_every = FLAGS_restart_every;
  if (!(FLAGS_total_move_mm > 0)) FlagError("total_move_mm", "must be positive", "e.g. 20");
  if (!(FLAGS_round_move_mm >= 0)) FlagError("round_move_mm", "must be >= 0", "e.g. 2");
  if (FLAGS_round_evaluations < 1) FlagError("round_evaluations", "must be >= 1", "e.g. 10");
  RequireInRange("round_evals", static_cast<long>(FLAGS_round_evals), 0, 1000000,
                 "e.g. 40; 0 = one round");
  RequireInRange("candidates", static_cast<long>(FLAGS_candidates), 1, 10, "e.g. 3");
  options.limits.total = 1e-3 * FLAGS_total_move_mm;
  options.limits.per_round = 1e-3 * FLAGS_round_move_mm;
  options.limits.round_evaluations = FLAGS_round_evaluations;
  if (FLAGS_lbfgs_rank < 1) FlagError("lbfgs_rank", "must be >= 1", "e.g. 20");
  options.ceres.max_lbfgs_rank = FLAGS_lbfgs_rank;
  return options;
}

Budget BudgetFromFlags() {
  RequireInRange("max_evals", static_cast<long>(FLAGS_max_evals), 1, 1000000,
                 "e.g. --max_evals=200");
  RequireInRange("max_seconds", FLAGS_max_seconds, 0, 1e7, "seconds, 0 = unlimited");
  RequireInRange("gradient_tolerance", FLAGS_gradient_tolerance, 0, 1, "e.g. 1e-8");
  RequireInRange("function_tolerance", FLAGS_function_tolerance, 0, 1, "e.g. 1e-10");
  RequireInRange("parameter_tolerance", FLAGS_parameter_tolerance, 0, 1e3, "e.g. 1e-8");
  RequireInRange("target_reduction", FLAGS_target_reduction, -1e6, 100, "a percentage, e.g. 70");
  Budget budget;
  budget.max_evaluations = FLAGS_max_evals;
  budget.max_seconds = FLAGS_max_seconds;
  budget.gradient_tolerance = FLAGS_gradient_tolerance;
  budget.function_tolerance = FLAGS_function_tolerance;
  budget.parameter_tolerance = FLAGS_parameter_tolerance;
  return budget;
}

// The first history entry at or below (1 − target) φ₀, or nullptr.
const IterationRecord* FirstReaching(const OptimizerResult& result, double target_percent) {
  if (!result.ok) return nullptr;
  const double threshold = result.initial_phi * (1 - target_percent / 100);
  for (const IterationRecord& record : result.history)
    if (record.phi <= threshold) return &record;
  return nullptr;
}

void PrintTable(std::vector<OptimizerResult> results) {
  // Ranked by the fresh reduction: what a person placed on each kept design gets.
  std::stable_sort(
      results.begin(), results.end(), [](const OptimizerResult& a, const OptimizerResult& b) {
        return (a.ok ? a.ReductionPercent() : -1e300) > (b.ok ? b.ReductionPercent() : -1e300);
      });
  const std::string target = std::to_string(static_cast<int>(FLAGS_target_reduction)) + "%";
  std::cout << "\n"
            << std::left << std::setw(13) << "optimizer" << std::right << std::setw(13)
            << "fresh phi" << std::setw(10) << "fresh %" << std::setw(11) << "followed %"
            << std::setw(7) << "evals" << std::setw(8) << "newton" << std::setw(9) << "wall s"
            << std::setw(14) << ("evals to " + target) << std::setw(15) << ("newton to " + target)
            << "  "
            << "stop reason\n";
  for (const OptimizerResult& r : results) {
    const IterationRecord* reached = FirstReaching(r, FLAGS_target_reduction);
    const double followed =
        std::isfinite(r.followed_phi) ? 100 * (1 - r.followed_phi / r.initial_phi) : NAN;
    std::cout << std::left << std::setw(13) << r.optimizer << std::right << std::setprecision(5)
              << std::setw(13) << (r.ok ? r.best_phi : 0.0) << std::fixed << std::setprecision(1)
              << std::setw(10) << r.ReductionPercent() << std::setw(11) << followed << std::setw(7)
              << r.evaluations << std::setw(8) << r.newton_iterations << std::setw(9) << r.seconds
              << std::defaultfloat << std::setw(14)
              << (reached ? std::to_string(reached->evaluations) : "-") << std::setw(15)
              << (reached ? std::to_string(reached->newton_iterations) : "-") << "  "
              << r.stop_reason << "\n";
  }
}

void Plot(const std::string& out_dir, const std::string& final_dir) {
  if (!FLAGS_plot) return;
  const std::string script =
      !FLAGS_plot_script.empty() ? FLAGS_plot_script : ToolScriptPath("plot_compare.py");
  if (!std::filesystem::exists(script)) {
    std::cerr << "ergo_compare: warning: plot script " << script
              << " not found (give --plot_script); compare.png not written\n";
    return;
  }
  const std::string python = FindPythonWithMatplotlib(FLAGS_python);
  if (python.empty()) {
    std::cerr << "ergo_compare: warning: no python3 with matplotlib found (Debian: apt-get "
                 "install python3-matplotlib); compare.png not written\n";
    return;
  }
  // An argument vector, never a shell: --out may hold any character.
  const std::vector<std::string> command = {python, script, out_dir};
  const ChildProcessResult plotted = RunChildProcess(command);
  if (!plotted.ok()) {
    std::cerr << "ergo_compare: warning: " << CommandLineForDisplay(command) << " "
              << plotted.Describe() << "; compare.png not written\n";
    return;
  }
  std::cout << "wrote " << final_dir << "/compare.png\n";
}

int Compare() {
  std::vector<std::string> names = NonEmptyItems(FLAGS_optimizers);
  if (names.empty()) FlagError("optimizers", "is empty", "e.g. --optimizers=paper-ncg,steepest");
  const OptimizerOptions options = OptionsFromFlags();
  const Budget budget = BudgetFromFlags();
  for (const std::string& name : names) {
    std::string error;
    if (!MakeOptimizer(name, options, &error)) FlagError("optimizers", error, "fix the list");
  }
  if (FLAGS_out.empty()) FlagError("out", "is required", "give the output directory, --out=DIR");
  StopOnSignals signals;
  OutputDirectory output(FLAGS_out, "--out");  // writable, checked before any work
  const std::string out_dir = output.path();

  Scenario scenario;
  try {
    scenario = ScenarioFromFlags();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("--scenario=" + FLAGS_scenario, "",
                     std::string("the scenario could not be built: ") + e.what(),
                     "check the scenario's flags");
  }
  std::cout << "scenario " << scenario.name << ": " << scenario.description << "\n";
  // The same problem as ergo_optimize poses from the same flags (γ fixed once, on x₀).
  ApplyDesignFlags(&scenario);
  double gamma = 0;
  {
    DesignProblem probe = scenario.MakeProblem();
    gamma = ApplyGammaFlags(&probe);
  }
  scenario.design.gamma = gamma;
  // The fresh score every kept design must earn (the same for every optimiser).
  DesignProblem fresh = scenario.MakeProblem();
  fresh.set_placement(DesignPlacement::kFresh);
  const Eigen::VectorXd x0 = fresh.InitialDesign();
  const DesignEvaluation start = DesignProblem(fresh).Evaluate(x0, false);
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_compare: interrupted before any result; nothing written\n";
    return StopOnSignals::ExitCode();
  }
  if (!start.ok) {
    std::cerr << "ergo_compare: the initial equilibrium failed: " << start.message << "\n";
    return 1;
  }
  // The objective every optimiser minimises (the mean over placements when robust), and the
  // fresh score their kept designs must earn, as ergo_optimize poses them.
  const std::vector<Placement> robust =
      RobustPlacements(*scenario.body, RobustPlacementsFlag(), RobustShiftFlag(), RobustTiltFlag());
  RoundsProblem rounds_problem;
  rounds_problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming* timing) {
    std::string failure;
    const double phi = MeanPlacedPhi(fresh, x, robust, &StopOnSignals::flag(), timing, &failure);
    // A design the body finds no equilibrium on afresh is not kept; say why.
    if (!failure.empty() && !StopOnSignals::stopped())
      std::cout << "  placed afresh: no equilibrium at " << failure << "\n";
    return phi;
  };
  const auto fresh_start = std::chrono::steady_clock::now();
  const double phi0 = robust.size() > 1 ? rounds_problem.fresh_score(x0, nullptr) : start.phi;
  RoundsOptions rounds_options;
  rounds_options.round_evaluations = FLAGS_round_evals;
  rounds_options.candidates = FLAGS_candidates;
  // The time of one fresh score, so a time budget keeps room for the rounds' checks.
  rounds_options.fresh_score_seconds =
      robust.size() > 1 ? SecondsSince(fresh_start) : start.timing.total_seconds;

  std::vector<OptimizerResult> results;
  bool crashed = false;
  for (const std::string& name : names) {
    if (StopOnSignals::stopped()) {
      std::cout << name << ": not run (interrupted)\n";
      continue;
    }
    std::unique_ptr<Optimizer> optimizer = MakeOptimizer(name, options, nullptr);
    // Every optimiser from a fresh problem: no warm starts leak between them.
    const DesignProblem base = scenario.MakeProblem();
    rounds_problem.make_objective = [&]() -> std::unique_ptr<Objective> {
      if (robust.size() > 1) return std::make_unique<RobustDesignObjective>(base, robust);
      return std::make_unique<DesignObjective>(base);
    };
    std::cout << "\n" << name << " on " << DesignObjective(base).Describe() << "\n";
    RunControl control;
    control.stop = &StopOnSignals::flag();
    if (FLAGS_progress) {
      control.progress = [&name](const IterationRecord& r) {
        std::cout << "  " << name << " it " << r.iteration << ": phi " << std::setprecision(6)
                  << r.phi << ", " << r.evaluations << " evals, " << r.newton_iterations
                  << " newton, " << std::setprecision(3) << r.seconds << " s, step " << r.step * 1e3
                  << " mm" << std::endl;
        return true;
      };
    }
    OptimizerResult result;
    try {
      result =
          MinimizeInRounds(*optimizer, rounds_problem, x0, phi0, budget, control, rounds_options)
              .result;
    } catch (const std::exception& e) {
      crashed = true;
      result.optimizer = name;
      result.stop_reason = std::string("crashed: ") + e.what();
    }
    std::cout << result.BriefReport() << " (kept design placed afresh; on its path "
              << (std::isfinite(result.followed_phi) ? result.followed_phi : phi0) << ")\n";
    WriteHistoryCsv(out_dir + "/" + name + "_history.csv", result);
    results.push_back(std::move(result));
  }
  WriteComparisonCsv(out_dir + "/compare.csv", results);
  PrintTable(results);
  if (FLAGS_plot && !StopOnSignals::stopped()) Plot(out_dir, output.final_path());
  std::string error;
  if (!output.Commit(&error)) {
    std::cerr << "ergo_compare: " << error << "\n";
    return 1;
  }
  std::cout << "\nwrote " << output.final_path() << "/compare.csv and " << results.size()
            << " history CSVs\n";
  if (crashed) return 1;
  return StopOnSignals::stopped() ? StopOnSignals::ExitCode() : 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(ergo::kUsage);
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_compare: " << error.what() << "\nusage: " << ergo::kUsage << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Compare();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_compare: " << error.what() << "\n";
    return 2;
  }
}
