// ergo_population: one support design for a population of bodies (a manufacturer's one insole
// for many feet, a foot as it swells or stiffens). Reads a population file
// (problems/population.h: a scene flagfile, the flags of the shared support, each body's
// flags and weight), builds every body on the one support, and optimises the aggregate of
// the bodies' scores — mean, mean + k·std, a smooth worst case or CVaR
// (solvers/population_objective.h) — through the same rounds as ergo_optimize (each round's
// designs re-scored with every body placed afresh). Then it scores the design optimised for
// the population's mean body alone on every body, for comparison. Outputs in --out:
// summary.json / summary.md / bodies.csv (per body: fresh scores and peak pressures before
// and after), history.csv, population.json, the support as PLY / STL (mm) and each body's
// VTUs, and population.png.
//
// Under `mpirun -np N ergo_population --mpi …` the bodies are spread over the ranks (body b
// on rank b mod N); every rank runs the same optimiser and the ranks' figures are combined
// by exact reductions, so the design is the single-process one bit for bit; rank 0 writes.
//
//   ergo_population --population=data/shoe_population.json --objective=worst --out=DIR
//   ergo_population --generate=FILE --scene_flagfile=data/shoe.flags --count=8
//       --vary=shoe_foot_length=0.24:0.28,shoe_modulus_scale=0.7:1.3
//       --support_at=shoe_foot_length=high
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <omp.h>

#include "ergo/design/placement_checks.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/blas_threads.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"
#include "problems/population.h"
#include "solvers/design_objective.h"
#include "solvers/fresh_rounds.h"
#include "solvers/fresh_score_objective.h"
#include "solvers/history_csv.h"
#include "solvers/optimizer.h"
#include "solvers/population_objective.h"
#include "solvers/robust_design_objective.h"
#include "tools/common/child_process.h"
#include "tools/common/design_flags.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"
#include "tools/common/population_scenarios.h"
#include "tools/common/ranks.h"
#include "tools/common/run_outputs.h"
#include "tools/common/run_signals.h"
#include "tools/common/vtu_flags.h"
#include "tools/ergo_population/population_report.h"

DEFINE_string(population, "",
              "the population file (JSON; problems/population.h), e.g. "
              "data/shoe_population.json");
DEFINE_string(objective, "mean",
              "what the design minimises over the bodies' relative fresh scores r_b: mean, "
              "meanstd (mean + k·std), worst (smooth maximum) or cvar (mean of the worst 1 − α)");
DEFINE_double(std_weight, 1, "meanstd: k");
DEFINE_double(temperature, 0.05, "worst: the log-sum-exp temperature, in units of r");
DEFINE_double(cvar_alpha, 0.5, "cvar: α in [0, 1); the worst 1 − α of the population by weight");
DEFINE_string(optimizer, "nlopt-lbfgs",
              "optimiser: paper-ncg, steepest, ceres-lbfgs, ceres-ncg, nlopt-mma, nlopt-ccsaq, "
              "nlopt-tnewton, nlopt-lbfgs");
DEFINE_int32(max_evals, 40, "budget: population evaluations (fresh re-scoring included)");
DEFINE_double(max_seconds, 0, "budget: wall seconds; 0 = unlimited");
DEFINE_int32(round_evals, 40, "evaluations per round (see ergo_optimize --help); 0 = one round");
DEFINE_int32(candidates, 3, "designs of each round placed afresh before one is kept");
DEFINE_string(out, "population_out", "output directory (created if missing; replaced as a whole)");
DEFINE_bool(mpi, false,
            "spread the bodies over the ranks of mpirun (mpirun -np N ergo_population --mpi ...)");
DEFINE_bool(compare_mean_body, true,
            "also optimise for the population's mean body alone (the file's \"mean_body\") with "
            "the same budget, and score that design on every body");
DEFINE_int32(threads, 0, "threads per rank (0 = the machine's cores shared among its ranks)");
DEFINE_bool(plot, true, "write population.png with tools/plot_population.py (matplotlib)");
DEFINE_bool(progress, true, "print one line per iteration (rank 0)");
DEFINE_string(generate, "",
              "write a generated population file to this path and stop (with --vary, --count, "
              "--seed, --scene_flagfile, --support_at)");
DEFINE_string(vary, "",
              "--generate: comma-separated FLAG=LOW:HIGH ranges, e.g. "
              "shoe_foot_length=0.24:0.28,shoe_modulus_scale=0.7:1.3");
DEFINE_int32(count, 8, "--generate: bodies");
DEFINE_int32(seed, 1, "--generate: the Latin hypercube's shuffle");
DEFINE_string(scene_flagfile, "", "--generate: the scene flagfile every body starts from");
DEFINE_string(support_at, "",
              "--generate: FLAG=high|low (comma-separated): the shared support's value of a "
              "varied flag, e.g. shoe_foot_length=high (a sole every foot fits on)");

namespace ergo {
namespace {

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

// --generate: a Latin-hypercube population written as a file.
int Generate() {
  PopulationGenerator generator;
  for (const std::string& range : SplitCommas(FLAGS_vary))
    generator.ranges.push_back(ParseFlagRange(range, "--vary"));
  RequireInRange("count", static_cast<long>(FLAGS_count), 1, 10000, "e.g. 8");
  RequireInRange("seed", static_cast<long>(FLAGS_seed), 0, 1L << 31, "e.g. 1");
  generator.count = FLAGS_count;
  generator.seed = static_cast<unsigned>(FLAGS_seed);
  const std::filesystem::path file = std::filesystem::absolute(FLAGS_generate);
  if (!FLAGS_scene_flagfile.empty()) {
    if (!std::filesystem::is_regular_file(FLAGS_scene_flagfile))
      throw InputError("--scene_flagfile", "", "'" + FLAGS_scene_flagfile + "' is not a file",
                       "give a scene flagfile, e.g. data/shoe.flags");
    generator.flagfile = std::filesystem::relative(std::filesystem::absolute(FLAGS_scene_flagfile),
                                                   file.parent_path())
                             .string();
  }
  for (const std::string& entry : SplitCommas(FLAGS_support_at)) {
    const size_t equals = entry.find('=');
    const std::string flag = entry.substr(0, equals),
                      end = equals == std::string::npos ? "" : entry.substr(equals + 1);
    const bool varied = std::any_of(generator.ranges.begin(), generator.ranges.end(),
                                    [&](const FlagRange& r) { return r.flag == flag; });
    if ((end != "high" && end != "low") || !varied)
      throw InputError("--support_at", "", "'" + entry + "' is not FLAG=high|low of a --vary flag",
                       "e.g. shoe_foot_length=high");
    generator.support_at[flag] = end;
  }
  std::ostringstream description;
  description << generator.count << " bodies";
  for (const FlagRange& r : generator.ranges)
    description << ", " << r.flag << " " << r.low << "–" << r.high;
  generator.description = description.str();
  const PopulationSpec spec = GeneratePopulation(generator);
  WriteJsonFile(file.string(), PopulationJson(spec));
  std::cout << "wrote " << file.string() << ": " << spec.description << "\n";
  return 0;
}

void ValidateRunFlags(PopulationOptions* options) {
  if (FLAGS_population.empty())
    throw InputError("--population", "", "is missing",
                     "give a population file, e.g. --population=data/shoe_population.json");
  if (!ParsePopulationAggregate(FLAGS_objective, &options->aggregate))
    throw InputError("--objective", "", "'" + FLAGS_objective + "' is unknown",
                     "use mean, meanstd, worst or cvar");
  RequireInRange("std_weight", FLAGS_std_weight, 0, 100, "e.g. 1");
  RequireInRange("temperature", FLAGS_temperature, 1e-4, 10, "e.g. 0.05");
  RequireInRange("cvar_alpha", FLAGS_cvar_alpha, 0, 0.99, "e.g. 0.5");
  options->std_weight = FLAGS_std_weight;
  options->temperature = FLAGS_temperature;
  options->cvar_alpha = FLAGS_cvar_alpha;
  RequireInRange("max_evals", static_cast<long>(FLAGS_max_evals), 1, 1000000, "e.g. 40");
  RequireInRange("max_seconds", FLAGS_max_seconds, 0, 1e7, "seconds, 0 = unlimited");
  RequireInRange("round_evals", static_cast<long>(FLAGS_round_evals), 0, 1000000, "e.g. 40");
  RequireInRange("candidates", static_cast<long>(FLAGS_candidates), 1, 10, "e.g. 3");
  RequireInRange("threads", static_cast<long>(FLAGS_threads), 0, 1024, "0 = all cores");
  RobustPlacementsFlag();
  std::string error;
  if (!MakeOptimizer(FLAGS_optimizer, OptimizerOptions(), &error))
    throw InputError("--optimizer", "", "'" + FLAGS_optimizer + "' is unknown", error);
}

// One body of the population, on the rank that owns it.
struct Body {
  int index = 0;
  std::string name;
  Scenario scenario;
  std::unique_ptr<DesignProblem> path;   // the optimiser's (γ set)
  std::unique_ptr<DesignProblem> fresh;  // placed afresh
  std::vector<Placement> robust;         // the objective's placements
  double scale = 0;                      // its objective at x₀, placed afresh
  double initial_peak = 0;
};

// The body of `flags` on the shared support (the support scenario's mesh, designed vertices
// and design space); its γ and scale from its first evaluation at x₀. Throws InputError for
// unusable flags and std::runtime_error when it finds no equilibrium on the initial support.
Body MakeBody(const PopulationSpec& spec, const FlagValues& flags, const std::string& name,
              const Scenario& support, const std::atomic<bool>* stop) {
  Body body;
  body.name = name;
  body.scenario = ScenarioWithFlags(spec, flags, "body " + name);
  DesignOptions design = body.scenario.design;
  design.parameterization = support.design.parameterization;
  design.filter_radius = support.design.filter_radius;
  design.active = support.design.active;
  body.path = std::make_unique<DesignProblem>(*body.scenario.body, support.support,
                                              body.scenario.start, design);
  body.fresh = std::make_unique<DesignProblem>(*body.path);
  body.fresh->set_placement(DesignPlacement::kFresh);
  body.fresh->ClearWarmStarts();
  const Eigen::VectorXd x0 = body.path->InitialDesign();
  const DesignEvaluation first = DesignProblem(*body.fresh).Evaluate(x0, false);
  if (!first.ok)
    throw std::runtime_error("body " + name +
                             ": the body placed on the initial support did not reach "
                             "equilibrium: " +
                             first.message);
  const double gamma = ApplyGammaFlags(body.path.get(), &first);
  body.fresh->set_gamma(gamma);
  DesignEvaluation initial = first;
  initial.phi = first.zeta + gamma * first.psi;
  body.robust = RobustPlacements(*body.scenario.body, RobustPlacementsFlag(), RobustShiftFlag(),
                                 RobustTiltFlag());
  // The scale is the fresh objective's own value at x₀ (r_b = 1 there to the last bit; the
  // first evaluation above starts its solve from the scene's pose, not a placement's).
  body.scale = FreshScoreObjective(*body.fresh, body.robust, stop).Evaluate(x0, false).phi;
  body.initial_peak = ReportEvaluation(*body.fresh, x0, std::move(initial)).peak_pressure;
  if (!(body.scale > 0))
    throw std::runtime_error("body " + name + ": its score on the initial support is " +
                             std::to_string(body.scale) +
                             " (no contact at some placement?): it cannot be a reference");
  return body;
}

// The population objective over `bodies` (this rank's; the others' members are empty):
// each body's optimiser path, or (fresh) its fresh score.
std::unique_ptr<PopulationObjective> MakePopulationObjective(
    const PopulationSpec& spec, const std::vector<double>& scales, std::vector<Body>& bodies,
    const PopulationOptions& options, bool fresh, Ranks& ranks, const std::atomic<bool>* stop) {
  std::vector<PopulationMember> members;
  for (size_t b = 0; b < spec.bodies.size(); ++b)
    members.push_back({spec.bodies[b].name, spec.bodies[b].weight, scales[b], nullptr});
  for (Body& body : bodies) {
    PopulationMember& member = members[body.index];
    if (fresh) {
      member.objective = std::make_unique<FreshScoreObjective>(*body.fresh, body.robust, stop);
    } else {
      DesignProblem path(*body.path);
      path.ClearWarmStarts();
      if (body.robust.size() > 1)
        member.objective = std::make_unique<RobustDesignObjective>(path, body.robust);
      else
        member.objective = std::make_unique<DesignObjective>(path);
    }
  }
  return std::make_unique<PopulationObjective>(std::move(members), options, ranks.NewExchange());
}

struct Optimised {
  RoundsResult rounds;
  Eigen::VectorXd kept;
};

// MinimizeInRounds on `objective` (a fresh twin `fresh` scores the kept designs), with the
// run flags' optimiser and budget.
Optimised Optimise(const std::function<std::unique_ptr<Objective>()>& make_path,
                   PopulationObjective& fresh, const Eigen::VectorXd& x0, double phi0, Ranks& ranks,
                   const std::string& label) {
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer(FLAGS_optimizer, OptimizerOptions(), &error);
  RoundsProblem problem;
  problem.make_objective = make_path;
  problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming* timing) {
    const ObjectiveValue value = fresh.Evaluate(x, false);
    if (timing) *timing += value.timing;
    return value.ok ? value.phi : std::numeric_limits<double>::quiet_NaN();
  };
  Budget budget;
  budget.max_evaluations = FLAGS_max_evals;
  // Under MPI rank 0's clock decides for every rank (Ranks::WishStop), never each its own.
  budget.max_seconds = ranks.mpi() ? 0 : FLAGS_max_seconds;
  RunControl control;
  control.stop = &ranks.stop();
  const auto begin = std::chrono::steady_clock::now();
  double best = phi0;
  control.progress = [&](const IterationRecord& r) {
    best = std::min(best, r.phi);
    if (ranks.mpi() && ranks.root() && FLAGS_max_seconds > 0 &&
        SecondsSince(begin) > FLAGS_max_seconds)
      ranks.WishStop();
    if (FLAGS_progress && ranks.root()) {
      std::printf("%s iter %4d  F/F₀ %.4f  best %.4f  evals %4ld  elapsed %6.1f s\n", label.c_str(),
                  r.iteration, r.phi / phi0, best / phi0, r.evaluations, r.seconds);
      std::fflush(stdout);
    }
    return true;
  };
  RoundsOptions options;
  options.round_evaluations = FLAGS_round_evals;
  options.candidates = FLAGS_candidates;
  Optimised out;
  out.rounds = MinimizeInRounds(*optimizer, problem, x0, phi0, budget, control, options);
  out.kept = out.rounds.kept_x;
  return out;
}

// Every rank's error at a set-up step, as one exit: 2 for bad input, 1 for a failed
// computation; the first rank's message printed by rank 0.
int AgreeOnFailure(Ranks& ranks, const std::string& local_error) {
  const std::string error = ranks.FirstError(local_error);
  if (error.empty()) return 0;
  if (ranks.root()) std::cerr << "ergo_population: " << error.substr(2) << "\n";
  return error[0] == '2' ? 2 : 1;
}

int Run(int argc, char** argv) {
  if (!FLAGS_generate.empty()) return Generate();
  StopOnSignals signals;
  Ranks ranks(FLAGS_mpi, &argc, &argv, &StopOnSignals::flag());
  PopulationOptions options;
  PopulationSpec spec;
  std::unique_ptr<OutputDirectory> output;
  std::string error;
  try {
    ValidateRunFlags(&options);
    spec = ReadPopulationFile(FLAGS_population);
    ApplyPopulationFlagfile(spec, argc, argv);
    ValidateRunFlags(&options);  // the flagfile may set run flags too
    if (ranks.size() > static_cast<int>(spec.bodies.size()))
      throw InputError("mpirun -np", "",
                       std::to_string(ranks.size()) + " ranks for " +
                           std::to_string(spec.bodies.size()) + " bodies",
                       "use at most one rank per body");
    if (ranks.root()) output = std::make_unique<OutputDirectory>(FLAGS_out, "--out");
  } catch (const InputError& e) {
    error = std::string("2|") + e.what();
  }
  if (const int code = AgreeOnFailure(ranks, error)) return code;
  const VtuEncoding vtu_encoding = VtuEncodingFromFlags();
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  const int threads = FLAGS_threads > 0 ? FLAGS_threads : std::max(1, cores / ranks.local_size());
  omp_set_num_threads(threads);
  // One BLAS thread throughout: a body's figures then do not depend on how many threads its
  // process has (OpenBLAS rounds a product split over threads differently), which keeps a
  // run under mpirun bit for bit the single-process one; the cores go to bodies and assembly.
  const SingleThreadedBlas single_threaded_blas;
  const auto begin = std::chrono::steady_clock::now();
  const int count = static_cast<int>(spec.bodies.size());
  if (ranks.root())
    std::cout << "population " << spec.source << ": " << count << " bodies"
              << (spec.description.empty() ? "" : " (" + spec.description + ")") << " on "
              << ranks.size() << " rank(s) × " << threads << " thread(s)\n";

  // The shared support, then this rank's bodies on it.
  Scenario support;
  std::vector<Body> bodies;
  const std::atomic<bool>* stop = &ranks.stop();
  try {
    support = ScenarioWithFlags(spec, spec.support, "the support");
    for (int b = 0; b < count; ++b) {
      if (!ranks.Owns(b)) continue;
      bodies.push_back(MakeBody(spec, spec.bodies[b].flags, spec.bodies[b].name, support, stop));
      bodies.back().index = b;
      std::cout << "  body " << spec.bodies[b].name << " (rank " << ranks.rank()
                << "): score on the initial support " << bodies.back().scale << ", peak "
                << bodies.back().initial_peak / 1e3 << " kPa\n";
    }
  } catch (const InputError& e) {
    error = std::string("2|") + e.what();
  } catch (const std::exception& e) {
    error = std::string("1|") + e.what();
  }
  if (const int code = AgreeOnFailure(ranks, error)) return code;
  std::vector<double> scales(count, 0.0), initial_peaks(count, 0.0);
  for (const Body& body : bodies) {
    scales[body.index] = body.scale;
    initial_peaks[body.index] = body.initial_peak;
  }
  ranks.SumDisjoint(&scales);
  ranks.SumDisjoint(&initial_peaks);

  if (ranks.root())
    std::cout << "set up in " << SecondsSince(begin) << " s; optimising the " << FLAGS_objective
              << " over " << count << " bodies\n";
  const Eigen::VectorXd x0 = bodies.front().path->InitialDesign();
  std::unique_ptr<PopulationObjective> fresh =
      MakePopulationObjective(spec, scales, bodies, options, /*fresh=*/true, ranks, stop);
  const ObjectiveValue at_x0 = fresh->Evaluate(x0, false);
  const double phi0 = at_x0.phi;
  auto make_path = [&]() -> std::unique_ptr<Objective> {
    return MakePopulationObjective(spec, scales, bodies, options, /*fresh=*/false, ranks, stop);
  };
  const long long bytes_before = ranks.BytesSent();
  Optimised population = Optimise(make_path, *fresh, x0, phi0, ranks, "population");
  const long evaluations = std::max(1L, population.rounds.result.evaluations);

  PopulationSummary summary;
  summary.population = spec.source;
  summary.description = spec.description;
  summary.objective = PopulationAggregateName(options.aggregate);
  summary.objective_options = {{"std_weight", options.std_weight},
                               {"temperature", options.temperature},
                               {"cvar_alpha", options.cvar_alpha}};
  summary.optimizer = FLAGS_optimizer;
  summary.ranks = ranks.size();
  summary.threads = threads;
  // Placements per body (the tilts' count follows the scene's lock, the same for every body).
  summary.robust_placements =
      bodies.empty() ? RobustPlacementsFlag() : static_cast<int>(bodies.front().robust.size());
  summary.initial_score = phi0;
  summary.result = population.rounds.result;
  summary.bytes_per_evaluation = (ranks.BytesSent() - bytes_before) / evaluations;
  // Each body's score on the kept design (the fresh objective's members).
  const ObjectiveValue kept = fresh->Evaluate(population.kept, false);
  summary.optimized_score = kept.ok ? kept.phi : NAN;
  std::vector<double> kept_scores(count), mean_scores(count, NAN);
  for (int b = 0; b < count; ++b) kept_scores[b] = fresh->last_values()[b].phi;

  if (ranks.root())
    std::cout << "population design after " << SecondsSince(begin) << " s: " << kept.phi / phi0
              << " of the start" << (summary.mean_design ? "; now the mean body alone" : "")
              << "\n";
  // The mean body's own design (rank 0), scored on every body.
  summary.mean_design = FLAGS_compare_mean_body && !spec.mean_body.empty();
  Eigen::VectorXd mean_x = Eigen::VectorXd::Zero(x0.size());
  error.clear();
  if (summary.mean_design && ranks.root()) {
    try {
      std::vector<Body> mean_body;
      mean_body.push_back(MakeBody(spec, spec.mean_body, "mean", support, stop));
      PopulationSpec alone = spec;
      alone.bodies = {PopulationBody{"mean", 1, spec.mean_body}};
      Ranks single(&StopOnSignals::flag());
      const std::vector<double> scale = {mean_body.front().scale};
      std::unique_ptr<PopulationObjective> mean_fresh =
          MakePopulationObjective(alone, scale, mean_body, options, true, single, stop);
      auto make_mean = [&]() -> std::unique_ptr<Objective> {
        return MakePopulationObjective(alone, scale, mean_body, options, false, single, stop);
      };
      mean_x = Optimise(make_mean, *mean_fresh, x0, mean_fresh->Evaluate(x0, false).phi, single,
                        "mean body")
                   .kept;
    } catch (const std::exception& e) {
      error = std::string("1|the mean body: ") + e.what();
    }
  }
  if (summary.mean_design) {
    if (const int code = AgreeOnFailure(ranks, error)) return code;
    std::vector<double> shared(mean_x.data(), mean_x.data() + mean_x.size());
    ranks.SumDisjoint(&shared);  // rank 0's design on every rank
    mean_x = Eigen::Map<const Eigen::VectorXd>(shared.data(), x0.size());
    const ObjectiveValue on_population = fresh->Evaluate(mean_x, false);
    summary.mean_design_score = on_population.ok ? on_population.phi : NAN;
    for (int b = 0; b < count; ++b)
      mean_scores[b] = fresh->last_values()[b].ok ? fresh->last_values()[b].phi : NAN;
  }

  if (ranks.root() && summary.mean_design)
    std::cout << "mean body's design after " << SecondsSince(begin)
              << " s: " << summary.mean_design_score / phi0 << " of the start on the population\n";
  // Each body's centred report on the kept design (and the mean body's), and its files.
  const std::string out_dir = ranks.Broadcast(ranks.root() ? output->path() : "");
  std::vector<double> peaks(2 * count, 0.0);
  error.clear();
  try {
    for (Body& body : bodies) {
      const DesignReport initial = ReportDesign(*body.fresh, x0);
      const DesignReport optimized = ReportDesign(*body.fresh, population.kept);
      peaks[body.index] = optimized.peak_pressure;
      if (summary.mean_design)
        peaks[count + body.index] = ReportDesign(*body.fresh, mean_x).peak_pressure;
      WriteDesignVtus(out_dir, body.name + "_initial", *body.scenario.body, initial,
                      support.support.vertices, vtu_encoding);
      WriteDesignVtus(out_dir, body.name + "_optimized", *body.scenario.body, optimized,
                      support.support.vertices, vtu_encoding);
    }
  } catch (const std::exception& e) {
    error = std::string("1|") + e.what();
  }
  if (const int code = AgreeOnFailure(ranks, error)) return code;
  ranks.SumDisjoint(&peaks);
  summary.interrupted = StopOnSignals::stopped();
  summary.wall_seconds = SecondsSince(begin);
  if (!ranks.root()) return 0;

  double total_weight = 0;
  for (const PopulationBody& b : spec.bodies) total_weight += b.weight;
  for (int b = 0; b < count; ++b) {
    BodyOutcome outcome;
    outcome.name = spec.bodies[b].name;
    outcome.weight = spec.bodies[b].weight / total_weight;
    outcome.flags = spec.bodies[b].flags;
    outcome.initial_score = scales[b];
    outcome.optimized_score = kept_scores[b];
    outcome.initial_peak = initial_peaks[b];
    outcome.optimized_peak = peaks[b];
    outcome.mean_design_score = mean_scores[b];
    outcome.mean_design_peak = summary.mean_design ? peaks[count + b] : NAN;
    summary.bodies.push_back(outcome);
  }
  const std::filesystem::path out(out_dir);
  WriteSupportMeshes(out_dir, "initial", support.support);
  WriteSupportMeshes(out_dir, "optimized", bodies.front().fresh->SupportAt(population.kept));
  if (summary.mean_design)
    WriteSupportMeshes(out_dir, "mean_body", bodies.front().fresh->SupportAt(mean_x));
  WriteHistoryCsv((out / "history.csv").string(), summary.result);
  WriteJsonFile((out / "population.json").string(), PopulationJson(spec));
  WriteJsonFile((out / "summary.json").string(), PopulationSummaryJson(summary));
  WriteBodiesCsv((out / "bodies.csv").string(), summary);
  const std::string markdown = PopulationSummaryMarkdown(summary);
  WriteFileAtomically((out / "summary.md").string(), [&](std::ostream& s) { s << markdown; });
  if (FLAGS_plot && !summary.interrupted)
    RunPictureScript("ergo_population", "plot_population.py", out_dir);
  if (!output->Commit(&error)) {
    std::cerr << "ergo_population: " << error << "\n";
    return 1;
  }
  std::cout << markdown << "wrote " << output->final_path() << "/\n";
  return summary.interrupted ? StopOnSignals::ExitCode() : 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetCommandLineOptionWithMode("scenario", "shoe", gflags::SET_FLAGS_DEFAULT);
  gflags::SetUsageMessage(
      "one support design for a population of bodies\n"
      "  ergo_population --population=FILE [--objective=mean|meanstd|worst|cvar] [--out=DIR]\n"
      "  mpirun -np N ergo_population --mpi --population=FILE ...\n"
      "  ergo_population --generate=FILE --scene_flagfile=F --vary=FLAG=LOW:HIGH,... "
      "[--count=N]");
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_population: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, false);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_population: " << error.what() << "\n";
    return 2;
  }
}
