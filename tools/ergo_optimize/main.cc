// ergo_optimize: the designer's main job (paper §4–5). Takes a scenario (chair, shoe sole,
// mouse, …: --flagfile=data/SCENARIO.flags, any flag overridable), optimises the support's
// shape for even contact pressure with the chosen optimiser and budget, and writes to --out
// (default ./ergo_out): summary.md / summary.json (the paper's Table 1 columns with the body
// placed afresh on the kept design as the headline, the optimiser's own path beside it,
// placement checks, the skin's side of the score), history.csv, the initial and optimised
// support as PLY and print-ready STL (mm), body and support VTU with pressure and
// displacement fields, and PNG pictures. The outputs appear as one unit (a killed run
// leaves the previous complete set or none). Ctrl-C or SIGTERM stops cleanly and writes
// everything for the best design so far (exit 130 / 143); a second signal ends at once.
// With no flags: the quick shoe sole.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/design/placement_checks.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/seconds_since.h"
#include "solvers/design_objective.h"
#include "solvers/fresh_rounds.h"
#include "solvers/geometric_baselines.h"
#include "solvers/history_csv.h"
#include "solvers/optimizer.h"
#include "solvers/robust_design_objective.h"
#include "tools/common/child_process.h"
#include "tools/common/design_flags.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"
#include "tools/common/run_outputs.h"
#include "tools/common/run_signals.h"
#include "tools/common/scenario_flags.h"
#include "tools/common/vtu_flags.h"
#include "tools/ergo_optimize/checkpoint.h"
#include "tools/ergo_optimize/run_summary.h"

DEFINE_string(optimizer, "nlopt-lbfgs",
              "optimiser: paper-ncg, steepest, ceres-lbfgs, ceres-ncg, nlopt-mma, nlopt-ccsaq, "
              "nlopt-tnewton, nlopt-lbfgs (default; ceres-lbfgs when --preset=paper and this flag "
              "is not given)");
DECLARE_string(preset);
DEFINE_string(designer, "ergo",
              "who designs the support: ergo (the optimiser, --optimizer) or a geometric "
              "baseline, sit-and-relax or pose-to-seat (solvers/geometric_baselines.h), scored "
              "and reported the same way");
DEFINE_string(start_designer, "none",
              "--designer=ergo: where the optimiser starts: none (the scene's initial design) or "
              "the design of a geometric baseline, sit-and-relax or pose-to-seat (paper §7: "
              "ergo started from the Sit & Relax surface); scores stay relative to the scene's "
              "initial design");
DEFINE_double(baseline_depth, 0.05,
              "sit-and-relax: how far the rigid skin is pushed into the flat support for its "
              "pressure map, m");
DEFINE_double(baseline_contact_distance, 0,
              "pose-to-seat: skin within this distance of the support is the contact set, m; 0 "
              "= every downward-facing skin vertex");
DEFINE_double(baseline_smoothness, 1,
              "both baselines: weight of the support's smoothness against the fit to the body");
DEFINE_int32(max_evals, 40,
             "budget: φ evaluations (each an equilibrium per placement of the objective), probes "
             "and fresh checks included; with --max_seconds and no --max_evals, no cap");
DEFINE_double(max_seconds, 0,
              "budget: wall seconds of the optimisation, its fresh checks included (the "
              "placement checks and the outputs follow it); 0 = unlimited");
DEFINE_string(out, "ergo_out", "output directory (created if missing; replaced as a whole)");
DEFINE_int32(post_smoothing, 0,
             "Taubin iterations applied to the optimised design's designed region (paper §5.1; "
             "chair: a few); kept only if the body placed afresh scores better");
DEFINE_int32(threads, 0,
             "threads for assembly, contact and the probes' equilibria (0 = all cores)");
DEFINE_bool(plot, true, "write PNG pictures with tools/plot_results.py (python3 + matplotlib)");
DEFINE_bool(progress, true, "print one line per iteration");
DEFINE_int32(round_evals, 40,
             "evaluations per round: the optimiser follows its own path for at most this many, "
             "then its best designs are placed afresh and the best starts the next round; 0 = "
             "one round with the whole budget");
DEFINE_int32(candidates, 3, "designs of each round placed afresh before one is kept");
DEFINE_string(resume, "",
              "continue the run whose output directory is DIR from its checkpoint "
              "(DIR.checkpoint.json), with its flags; --out defaults to DIR");
DEFINE_int32(checkpoint_every, 1,
             "write DIR.checkpoint.json after a round once at least this many evaluations have "
             "passed since the last one, and after every round that kept a new best design "
             "(rounds: --round_evals); 0 = no checkpoints");
DEFINE_bool(placement_checks, true,
            "score the initial and the kept design with the body placed off centre and tilted");
DEFINE_double(placement_shift_mm, 3,
              "placement checks: the body lands this far off along each horizontal axis, mm");
DEFINE_double(placement_tilt_deg, 1,
              "placement checks: and held tilted by this much about each rotation axis across the "
              "load that the core lock holds (the shoe's roll, the chair's sideways lean, "
              "the mouse's two tilts; 0: no tilts), degrees");

namespace ergo {
namespace {

// The evaluation budget of a run governed by its time budget alone (the flag's upper bound).
constexpr int kNoEvaluationCap = 1000000;

// The default optimiser by resolution, from ergo_compare at the paper presets (README, "Which
// optimiser?": ceres-lbfgs ahead on all three scenes with the same wall budget); the quick
// presets keep nlopt-lbfgs, which led there when last compared.
void ApplyOptimizerDefault() {
  if (gflags::GetCommandLineFlagInfoOrDie("optimizer").is_default && FLAGS_preset == "paper")
    FLAGS_optimizer = "ceres-lbfgs";
}

// Every flag of this tool checked before any work (the scene's and the problem's are checked
// where they are read, also before any computation).
void ValidateRunFlags() {
  RequireInRange("max_evals", static_cast<long>(FLAGS_max_evals), 1, 1000000,
                 "e.g. --max_evals=100");
  RequireInRange("max_seconds", FLAGS_max_seconds, 0, 1e7, "seconds, 0 = unlimited");
  RequireInRange("post_smoothing", static_cast<long>(FLAGS_post_smoothing), 0, 1000,
                 "Taubin iterations, e.g. 3; 0 = none");
  RequireInRange("threads", static_cast<long>(FLAGS_threads), 0, 1024, "0 = all cores");
  RequireInRange("round_evals", static_cast<long>(FLAGS_round_evals), 0, 1000000,
                 "e.g. 40; 0 = one round");
  RequireInRange("candidates", static_cast<long>(FLAGS_candidates), 1, 10, "e.g. 3");
  RequireInRange("checkpoint_every", static_cast<long>(FLAGS_checkpoint_every), 0, 100000000,
                 "evaluations, e.g. 1 (every round); 0 = none");
  RobustPlacementsFlag();
  RequireInRange("placement_shift_mm", FLAGS_placement_shift_mm, 0, 50, "millimetres, e.g. 3");
  RequireInRange("placement_tilt_deg", FLAGS_placement_tilt_deg, 0, 30, "degrees, e.g. 1");
  std::string error;
  if (!MakeOptimizer(FLAGS_optimizer, OptimizerOptions(), &error))
    throw InputError("--optimizer", "", "'" + FLAGS_optimizer + "' is unknown", error);
  if (FLAGS_designer != "ergo" && FLAGS_designer != "sit-and-relax" &&
      FLAGS_designer != "pose-to-seat")
    throw InputError("--designer", "", "'" + FLAGS_designer + "' is unknown",
                     "use ergo, sit-and-relax or pose-to-seat");
  if (FLAGS_start_designer != "none" && FLAGS_start_designer != "sit-and-relax" &&
      FLAGS_start_designer != "pose-to-seat")
    throw InputError("--start_designer", "", "'" + FLAGS_start_designer + "' is unknown",
                     "use none, sit-and-relax or pose-to-seat");
  if (FLAGS_start_designer != "none" && FLAGS_designer != "ergo")
    throw InputError("--start_designer", "", "only applies to --designer=ergo",
                     "drop --start_designer, or use --designer=ergo");
  RequireInRange("baseline_depth", FLAGS_baseline_depth, 1e-4, 0.5, "metres, e.g. 0.05");
  RequireInRange("baseline_contact_distance", FLAGS_baseline_contact_distance, 0, 0.5,
                 "metres; 0 = every downward-facing skin vertex");
  RequireInRange("baseline_smoothness", FLAGS_baseline_smoothness, 0, 1e6, "e.g. 1");
}

// The design of the geometric baseline `method` (sit-and-relax or pose-to-seat) with the
// --baseline_* flags.
BaselineDesign Baseline(const std::string& method, const DesignProblem& problem,
                        const BodyState& start) {
  BaselineOptions options;
  options.negative_image_depth = FLAGS_baseline_depth;
  options.contact_distance = FLAGS_baseline_contact_distance;
  options.fit.smoothness = FLAGS_baseline_smoothness;
  return method == "sit-and-relax" ? SitAndRelaxDesign(problem, start, options)
                                   : PoseToSeatDesign(problem, start, options);
}

// A geometric baseline's design in place of the optimiser's rounds: one fresh evaluation,
// reported like a one-step run so the summary, checks and files are those of any design.
RoundsResult BaselineRounds(const DesignProblem& problem, const BodyState& start,
                            const RoundsProblem& rounds_problem, double phi0) {
  const auto begin = std::chrono::steady_clock::now();
  const BaselineDesign design = Baseline(FLAGS_designer, problem, start);
  std::cout << design.Describe() << "\n";
  RoundsResult rounds;
  rounds.rounds = 1;
  rounds.kept_x = design.x;
  rounds.kept_fresh_phi = rounds_problem.fresh_score(design.x, &rounds.result.timing);
  rounds.kept_followed_phi = std::numeric_limits<double>::quiet_NaN();
  OptimizerResult& result = rounds.result;
  result.optimizer = FLAGS_designer;
  result.ok = std::isfinite(rounds.kept_fresh_phi);
  result.best_x = design.x;
  result.initial_phi = phi0;
  result.best_phi = rounds.kept_fresh_phi;
  result.evaluations = 1;
  result.seconds = SecondsSince(begin);
  result.stop_reason = "baseline: " + design.Describe();
  IterationRecord start_record, final_record;
  start_record.phi = phi0;
  final_record.iteration = 1;
  final_record.evaluations = 1;
  final_record.seconds = result.seconds;
  final_record.phi = rounds.kept_fresh_phi;
  result.history = {start_record, final_record};
  // The baseline's design is kept whatever it scores: a placement that finds no equilibrium
  // on it is reported as such (the summary's checks), not replaced by the initial design.
  if (!result.ok)
    std::cout << "the objective's placements did not all reach equilibrium on the "
              << FLAGS_designer << " design\n";
  return rounds;
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

// The pictures of the written outputs (tools/plot_results.py); a missing matplotlib or an
// interrupted plot is a warning, never a failure of the run.
void Plot(const std::string& dir) { RunPictureScript("ergo_optimize", "plot_results.py", dir); }

int Run() {
  ApplyOptimizerDefault();
  ValidateRunFlags();
  const VtuEncoding vtu_encoding = VtuEncodingFromFlags();
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  StopOnSignals signals;
  OutputDirectory output(FLAGS_out, "--out");  // writable, checked before any work
  Scenario scenario = ScenarioFromFlags();
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer(FLAGS_optimizer, OptimizerOptions(), &error);
  std::cout << "scenario " << scenario.name << ": " << scenario.description << "\n";

  const auto begin = std::chrono::steady_clock::now();
  ApplyDesignFlags(&scenario);  // exponent, smoothing, Taubin, contact stiffness, placement
  DesignProblem problem = scenario.MakeProblem();
  const Eigen::VectorXd x0 = problem.InitialDesign();
  // Everything reported is placed afresh; the optimiser's path is `problem`'s own mode.
  DesignProblem fresh(problem);
  fresh.set_placement(DesignPlacement::kFresh);
  fresh.ClearWarmStarts();
  // The initial design first: an equilibrium that fails there is a failed computation (exit
  // 1), not a bad flag; γ = auto then reads ζ and ψ off this evaluation.
  const DesignEvaluation first = DesignProblem(fresh).Evaluate(x0, false);
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_optimize: interrupted before any result; nothing written\n";
    return StopOnSignals::ExitCode();
  }
  if (!first.ok) {
    std::cerr << "ergo_optimize: the body placed on the initial support did not reach "
                 "equilibrium: "
              << first.message << "\n";
    return 1;
  }
  const double gamma = ApplyGammaFlags(&problem, &first);
  fresh.set_gamma(gamma);
  RunSummary summary;
  summary.scenario = &scenario;
  summary.optimizer = FLAGS_designer == "ergo" ? FLAGS_optimizer : FLAGS_designer;
  summary.placement = DesignPlacementName(scenario.design.placement);
  summary.gamma = gamma;
  DesignEvaluation initial_evaluation = first;
  initial_evaluation.phi = first.zeta + gamma * first.psi;  // φ with the γ just chosen
  summary.initial = ReportEvaluation(fresh, x0, std::move(initial_evaluation), scenario.regions);
  const DesignEvaluation& initial = summary.initial.evaluation;
  const double phi0 = initial.phi;
  std::cout << "  initial φ " << phi0 << " (ζ " << initial.zeta << ": skin " << initial.zeta_human
            << ", support " << initial.zeta_support << "; γψ " << gamma * initial.psi << "), "
            << initial.equilibrium.contact_vertices << " skin vertices in contact, peak "
            << summary.initial.peak_pressure / 1e3 << " kPa, max penetration "
            << initial.equilibrium.max_penetration * 1e3 << " mm\n";

  // The objective, and the score a kept design must earn placed afresh.
  const std::vector<Placement> robust =
      RobustPlacements(*scenario.body, RobustPlacementsFlag(), RobustShiftFlag(), RobustTiltFlag());
  summary.robust_placements = static_cast<int>(robust.size());
  RoundsProblem rounds_problem;
  rounds_problem.make_objective = [&]() -> std::unique_ptr<Objective> {
    DesignProblem path(problem);
    path.ClearWarmStarts();
    if (robust.size() > 1) return std::make_unique<RobustDesignObjective>(path, robust);
    return std::make_unique<DesignObjective>(path);
  };
  rounds_problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming* timing) {
    std::string failure;
    const double phi = MeanPlacedPhi(fresh, x, robust, &StopOnSignals::flag(), timing, &failure);
    // A design the body finds no equilibrium on afresh is not kept; say why.
    if (!failure.empty() && !StopOnSignals::stopped())
      std::cout << "  placed afresh: no equilibrium at " << failure << "\n";
    return phi;
  };
  double phi0_objective = phi0;
  double fresh_score_seconds = first.timing.total_seconds;  // to keep the checks in the budget
  if (robust.size() > 1) {
    const auto fresh_start = std::chrono::steady_clock::now();
    phi0_objective = rounds_problem.fresh_score(x0, nullptr);
    fresh_score_seconds = SecondsSince(fresh_start);
    std::cout << "objective: mean over " << robust.size() << " placements; at x₀ " << phi0_objective
              << "\n";
  }

  Budget budget;
  // A time budget given alone is the budget: the 40-evaluation default is for runs without one.
  const bool evaluations_given = !gflags::GetCommandLineFlagInfoOrDie("max_evals").is_default;
  budget.max_evaluations =
      FLAGS_max_seconds > 0 && !evaluations_given ? kNoEvaluationCap : FLAGS_max_evals;
  budget.max_seconds = FLAGS_max_seconds;
  std::cout << "budget: ";
  if (budget.max_evaluations == kNoEvaluationCap)
    std::cout << "no evaluation cap";
  else
    std::cout << budget.max_evaluations << " evaluations";
  if (FLAGS_max_seconds > 0) std::cout << ", " << FLAGS_max_seconds << " s wall";
  std::cout << "\n";
  RunControl control;
  control.stop = &StopOnSignals::flag();
  double best = phi0_objective;
  control.progress = [&](const IterationRecord& r) {
    best = std::min(best, r.phi);
    if (FLAGS_progress) {
      const double per_eval =
          r.evaluations > 0 ? r.seconds / static_cast<double>(r.evaluations) : 0;
      double eta = per_eval * static_cast<double>(std::max(
                                  0L, static_cast<long>(budget.max_evaluations) - r.evaluations));
      if (FLAGS_max_seconds > 0) eta = std::min(eta, std::max(0.0, FLAGS_max_seconds - r.seconds));
      std::printf("iter %4d  φ/φ₀ %.4f  best %.4f  evals %4ld  elapsed %6.1f s  ETA %6.1f s\n",
                  r.iteration, r.phi / phi0_objective, best / phi0_objective, r.evaluations,
                  r.seconds, eta);
      std::fflush(stdout);
    }
    return true;
  };
  RoundsOptions rounds_options;
  rounds_options.round_evaluations = FLAGS_round_evals;
  rounds_options.candidates = FLAGS_candidates;
  rounds_options.fresh_score_seconds = fresh_score_seconds;
  // Checkpoints after rounds (a round depends only on its start: resumable exactly).
  const std::string checkpoint = CheckpointPath(output.final_path());
  const std::string fingerprint = RunFingerprint();
  long checkpointed = 0;
  double checkpointed_phi = std::numeric_limits<double>::infinity();
  if (FLAGS_checkpoint_every > 0) {
    rounds_options.on_round = [&](const RoundsState& state) {
      // Every N evaluations, at every new best design and at the end.
      const bool new_best = state.kept_fresh_phi < checkpointed_phi;
      if (state.evaluations - checkpointed < FLAGS_checkpoint_every && !state.finished && !new_best)
        return;
      WriteCheckpoint(checkpoint, state, fingerprint);
      checkpointed = state.evaluations;
      checkpointed_phi = state.kept_fresh_phi;
    };
  }
  RoundsState resumed;
  if (!FLAGS_resume.empty()) {
    resumed = ReadCheckpoint(CheckpointPath(FLAGS_resume), fingerprint);
    checkpointed = resumed.evaluations;
    std::cout << "resuming after round " << resumed.rounds << " (" << resumed.evaluations
              << " evaluations, kept design " << resumed.kept_fresh_phi / phi0_objective
              << " of the start)\n";
  }
  // Where the optimiser starts: x₀, or a baseline's design (scored against x₀ all the same).
  Eigen::VectorXd x_start = x0;
  double phi_start = phi0_objective;
  if (FLAGS_designer == "ergo" && FLAGS_start_designer != "none")
    summary.start = FLAGS_start_designer;  // also after a resume (its score is then not known)
  if (FLAGS_designer == "ergo" && FLAGS_start_designer != "none" && FLAGS_resume.empty()) {
    const BaselineDesign design = Baseline(FLAGS_start_designer, problem, scenario.start);
    x_start = design.x;
    phi_start = rounds_problem.fresh_score(x_start, nullptr);
    summary.start_score = phi_start;
    std::cout << "start: " << design.Describe() << "; its objective " << phi_start << " ("
              << phi_start / phi0_objective << " of the initial design's)\n";
    if (!std::isfinite(phi_start)) {
      std::cerr << "ergo_optimize: the body placed on the " << FLAGS_start_designer
                << " design did not reach equilibrium; run without --start_designer, or "
                   "change the --baseline_* flags\n";
      return 1;
    }
  }
  const RoundsResult rounds =
      FLAGS_designer != "ergo"
          ? BaselineRounds(problem, scenario.start, rounds_problem, phi0_objective)
          : MinimizeInRounds(*optimizer, rounds_problem, x_start, phi_start, budget, control,
                             rounds_options, FLAGS_resume.empty() ? nullptr : &resumed);
  summary.result = rounds.result;
  summary.interrupted = StopOnSignals::stopped();
  summary.candidate_phi = rounds.candidate_phi;
  summary.candidate_fresh_phi = rounds.candidate_fresh_phi;
  summary.kept_candidate = rounds.kept_candidate;
  std::cout << summary.optimizer << ": " << rounds.rounds << " round(s), "
            << rounds.result.evaluations << " evaluations, " << rounds.result.newton_iterations
            << " Newton iterations; kept design placed afresh: "
            << rounds.kept_fresh_phi / phi0_objective << " of the start ("
            << rounds.result.stop_reason << ")\n";

  // The kept design placed afresh (the headline), and on the optimiser's own path.
  Eigen::VectorXd kept = rounds.kept_x;
  summary.optimized = ReportDesign(fresh, kept, scenario.regions);
  if (FLAGS_post_smoothing > 0 && summary.optimized.evaluation.ok && !StopOnSignals::stopped()) {
    const Eigen::VectorXd smoothed_x = PostSmooth(problem, kept, FLAGS_post_smoothing);
    DesignReport smoothed = ReportDesign(fresh, smoothed_x, scenario.regions);
    const bool better =
        smoothed.evaluation.ok && smoothed.evaluation.phi < summary.optimized.evaluation.phi;
    std::ostringstream line;
    line << "Post-smoothing (" << FLAGS_post_smoothing << " Taubin iterations): φ afresh "
         << summary.optimized.evaluation.phi << " → "
         << (smoothed.evaluation.ok ? smoothed.evaluation.phi : NAN)
         << (better ? " (kept)" : " (discarded)") << ".";
    summary.post_smoothing = line.str();
    std::cout << line.str() << "\n";
    if (better) {
      kept = smoothed_x;
      summary.optimized = std::move(smoothed);
    }
  }
  if (!summary.optimized.evaluation.ok) {
    std::cout << "the body placed afresh on the optimised design did not reach equilibrium ("
              << summary.optimized.evaluation.message << "); keeping the initial design\n";
    summary.kept_design_failure = summary.optimized.evaluation.message;
    kept = x0;
    summary.optimized = summary.initial;
  }
  // The optimiser's own value of the kept design, and its report on that path when the
  // path's state is at hand (not after a resume, nor for a post-smoothed design).
  const bool on_path = kept == rounds.kept_x;
  summary.followed_phi =
      on_path ? rounds.kept_followed_phi : std::numeric_limits<double>::quiet_NaN();
  if (rounds.kept_path && on_path) {
    DesignProblem& path = robust.size() == 1
                              ? static_cast<DesignObjective&>(*rounds.kept_path).problem()
                              : static_cast<RobustDesignObjective&>(*rounds.kept_path).problem(0);
    summary.followed = ReportDesign(path, kept);
    // The robust objective's value is a mean over placements; report the centred path's.
    if (robust.size() > 1 && summary.followed.evaluation.ok)
      summary.followed_phi = summary.followed.evaluation.phi;
  } else if (kept == x0) {
    summary.followed = summary.initial;
  }

  // Placement checks: the body landing a few millimetres off, or tilted.
  if (FLAGS_placement_checks && !StopOnSignals::stopped()) {
    const std::vector<Placement> placements =
        PlacementChecks(*scenario.body, 1e-3 * FLAGS_placement_shift_mm,
                        FLAGS_placement_tilt_deg * M_PI / 180, /*with_tilts=*/true);
    const std::vector<DesignEvaluation> at_initial =
        EvaluatePlacements(fresh, x0, placements, &StopOnSignals::flag());
    const std::vector<DesignEvaluation> at_kept =
        EvaluatePlacements(fresh, kept, placements, &StopOnSignals::flag());
    for (size_t i = 0; i < placements.size(); ++i) {
      PlacementOutcome outcome;
      outcome.placement = placements[i];
      outcome.ok = at_initial[i].ok && at_kept[i].ok;
      outcome.message = !at_initial[i].ok ? "initial: " + at_initial[i].message
                                          : "optimised: " + at_kept[i].message;
      outcome.initial_score = at_initial[i].phi;
      outcome.score = at_kept[i].phi;
      summary.checks.push_back(outcome);
      std::cout << "placement " << placements[i].name << ": "
                << (outcome.ok ? std::to_string(outcome.ReductionPercent()) +
                                     " % below the "
                                     "initial design"
                               : "did not converge (" + outcome.message + ")")
                << "\n";
    }
  }
  summary.interrupted = StopOnSignals::stopped();
  summary.wall_seconds = SecondsSince(begin);

  // Outputs, into the temporary directory that becomes --out as a whole.
  const std::filesystem::path out(output.path());
  const Vertices& initial_support = scenario.support.vertices;
  WriteDesignFiles(out.string(), "initial", *scenario.body, summary.initial, initial_support,
                   vtu_encoding);
  WriteDesignFiles(out.string(), "optimized", *scenario.body, summary.optimized, initial_support,
                   vtu_encoding);
  WriteHistoryCsv((out / "history.csv").string(), summary.result);
  WriteJsonFile((out / "summary.json").string(), SummaryJson(summary));
  const std::string markdown = SummaryMarkdown(summary);
  WriteFileAtomically((out / "summary.md").string(),
                      [&](std::ostream& stream) { stream << markdown; });
  WriteJsonFile((out / "plot_data.json").string(),
                PlotData(scenario, summary.initial, summary.optimized), 0);
  if (FLAGS_plot && !StopOnSignals::stopped()) Plot(out.string());
  if (!output.Commit(&error)) {
    std::cerr << "ergo_optimize: " << error << "\n";
    return 1;
  }
  std::cout << markdown << "wrote " << output.final_path() << "/\n";
  if (StopOnSignals::stopped()) {
    if (FLAGS_checkpoint_every > 0 && std::filesystem::exists(checkpoint))
      std::cout << "resume with: ergo_optimize --resume=" << output.final_path() << "\n";
    return StopOnSignals::ExitCode();
  }
  std::error_code removed;
  std::filesystem::remove(checkpoint, removed);  // the run is complete
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
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_optimize: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    if (!FLAGS_resume.empty()) {
      if (gflags::GetCommandLineFlagInfoOrDie("out").is_default) FLAGS_out = FLAGS_resume;
      ergo::ApplyCheckpointFlags(ergo::CheckpointPath(FLAGS_resume));
    }
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_optimize: " << error.what() << "\n";
    return 2;
  }
}
