// Design evaluations (φ and ∇φ, DesignProblem::Evaluate) with their time split
// (ergo/design/evaluation_timing.h) as counters: seconds per part ("assembly_s",
// "factorization_s", …, "other_s") and the counts (newton_iterations, factorizations,
// pcg_iterations, line_search_trials, adjoint_factorizations, …).
//
// BM_DesignEvaluationWithGradient: a soft ball on a bumpy plate at about 2k and 10k body
// vertices, warm after 0.1 mm design steps (the gradient part against the warm solve).
//
// BM_Paper{Cold,Warm,Gradient}/chair|shoe|mouse: the paper presets as ergo_optimize poses
// them (problems/*_scenario.h, FromPreset("paper"); the flagfiles' γ = 0, e = 3), each scene
// built once (tens of seconds, not timed):
//   Cold      the body placed afresh on the initial design (kFresh: no warm start);
//   Warm      after a typical optimiser step — the filtered design moved along −∇φ so that
//             the largest support vertex moves 0.2 mm — warm-started from the equilibrium
//             at x₀ (kFollowed: nearest cached state and the tangent predictor);
//   Gradient  the same warm evaluation, timed by its gradient part alone (manual time =
//             adjoint_s).
// One iteration each (a paper evaluation takes seconds):
//   build/bin/design_benchmark --benchmark_filter=Paper
#include <map>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "ergo/design/design_problem.h"
#include "problems/bump_scenario.h"
#include "problems/chair_scenario.h"
#include "problems/mouse_scenario.h"
#include "problems/shoe_scenario.h"
#include "tests/benchmarks/evaluation_counters.h"

namespace ergo {
namespace {

// --- The ball on the bump -----------------------------------------------------------------

double EdgeLengthFor(int thousands) { return thousands <= 2 ? 0.0097 : 0.0057; }

struct BumpFixture {
  Scenario scenario;
  std::unique_ptr<DesignProblem> problem;
  Eigen::VectorXd x0, step;
};

BumpFixture& BumpFor(int thousands) {
  static std::map<int, BumpFixture> cache;
  BumpFixture& f = cache[thousands];
  if (f.problem) return f;
  BumpScenarioOptions options;
  options.edge_length = EdgeLengthFor(thousands);
  options.contact_stiffness = 1e7;  // κ, Pa/m
  f.scenario = MakeBumpScenario(options);
  f.problem = std::make_unique<DesignProblem>(f.scenario.MakeProblem());
  f.x0 = f.problem->InitialDesign();
  const DesignEvaluation first = f.problem->Evaluate(f.x0, true);  // cold: not timed
  // A design step moving the largest vertex by 0.1 mm along −∇φ.
  f.step = -first.gradient * (1e-4 / first.gradient.cwiseAbs().maxCoeff());
  return f;
}

void BM_DesignEvaluationWithGradient(benchmark::State& state) {
  BumpFixture& f = BumpFor(static_cast<int>(state.range(0)));
  DesignEvaluation e;
  int k = 0;
  for (auto _ : state) {
    // A new design each time (0.1 mm further along −∇φ): a genuine warm re-solve.
    e = f.problem->Evaluate(f.x0 + (++k) * f.step, true);
  }
  ReportEvaluationCounters(state, f.scenario, e);
  state.counters["warm_solve_s"] = e.equilibrium.total_seconds;
  state.counters["gradient_over_solve"] = e.timing.adjoint_seconds / e.equilibrium.total_seconds;
}

BENCHMARK(BM_DesignEvaluationWithGradient)
    ->Arg(2)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(4);

// --- The paper presets --------------------------------------------------------------------

constexpr double kStep = 2e-4;  // m: the largest support vertex move of the warm step

struct PaperScene {
  Scenario scenario;
  std::unique_ptr<DesignProblem> pristine;  // no evaluation yet
  Eigen::VectorXd x0;
  // After the cold evaluation of x₀ (made by BM_PaperCold, or on demand): its gradient and
  // the problem holding its equilibrium, factor and warm-start cache.
  std::unique_ptr<DesignProblem> after_cold;
  Eigen::VectorXd step;  // along −∇φ(x₀), largest vertex move kStep
};

Scenario BuildPaperScene(const std::string& name) {
  if (name == "chair") return MakeChairScenario(ChairScenarioOptions::FromPreset("paper"));
  if (name == "shoe") return MakeShoeScenario(ShoeScenarioOptions::FromPreset("paper"));
  return MakeMouseScenario(MouseScenarioOptions::FromPreset("paper"));
}

PaperScene& PaperSceneFor(const std::string& name) {
  static std::map<std::string, PaperScene> cache;
  PaperScene& s = cache[name];
  if (s.pristine) return s;
  s.scenario = BuildPaperScene(name);
  s.scenario.design.gamma = 0;  // the flagfiles' (the filter keeps the design smooth)
  s.pristine = std::make_unique<DesignProblem>(s.scenario.MakeProblem());
  s.pristine->set_placement(DesignPlacement::kFresh);
  s.x0 = s.pristine->InitialDesign();
  return s;
}

// Keeps the problem after a cold evaluation of x₀ (with its gradient) for the warm steps.
void KeepColdEvaluation(PaperScene& s, const DesignProblem& problem, const DesignEvaluation& e) {
  if (s.after_cold || !e.ok) return;
  s.after_cold = std::make_unique<DesignProblem>(problem);
  s.after_cold->set_placement(DesignPlacement::kFollowed);
  const double largest = problem.parameterization().VertexMoves(e.gradient).maxCoeff();
  s.step = -e.gradient * (kStep / largest);
}

const DesignProblem* AfterCold(PaperScene& s) {
  if (!s.after_cold) {
    DesignProblem problem(*s.pristine);
    KeepColdEvaluation(s, problem, problem.Evaluate(s.x0, true));
  }
  return s.after_cold.get();
}

void BM_PaperCold(benchmark::State& state, const std::string& name) {
  PaperScene& s = PaperSceneFor(name);
  DesignEvaluation e;
  std::unique_ptr<DesignProblem> evaluated;
  for (auto _ : state) {
    state.PauseTiming();
    auto problem = std::make_unique<DesignProblem>(*s.pristine);
    state.ResumeTiming();
    e = problem->Evaluate(s.x0, true);
    evaluated = std::move(problem);
  }
  KeepColdEvaluation(s, *evaluated, e);
  ReportEvaluationCounters(state, s.scenario, e);
}

// A warm evaluation after the step (on a copy of the problem after the cold one, so every
// iteration and every benchmark takes the same step).
DesignEvaluation WarmStep(const PaperScene& s, const DesignProblem& after_cold,
                          benchmark::State& state, bool predictor = true) {
  state.PauseTiming();
  DesignProblem problem(after_cold);
  problem.set_tangent_predictor(predictor);
  state.ResumeTiming();
  return problem.Evaluate(s.x0 + s.step, true);
}

// A warm evaluation after a step; `gradient_only` times just its adjoint part (manual time);
// `predictor` = false starts Newton from the last equilibrium itself (issue 13's first lever,
// measured against the default).
void PaperWarmStep(benchmark::State& state, const std::string& name, bool gradient_only,
                   bool predictor = true) {
  PaperScene& s = PaperSceneFor(name);
  const DesignProblem* after_cold = AfterCold(s);
  if (!after_cold) {
    state.SkipWithError("the cold evaluation failed");
    return;
  }
  DesignEvaluation e;
  for (auto _ : state) {
    e = WarmStep(s, *after_cold, state, predictor);
    if (gradient_only) state.SetIterationTime(e.timing.adjoint_seconds);
  }
  ReportEvaluationCounters(state, s.scenario, e);
  state.counters["step_mm"] = 1e3 * kStep;
  if (gradient_only)
    state.counters["gradient_over_evaluation"] = e.timing.adjoint_seconds / e.timing.total_seconds;
}

void BM_PaperWarm(benchmark::State& state, const std::string& name) {
  PaperWarmStep(state, name, false);
}

void BM_PaperGradient(benchmark::State& state, const std::string& name) {
  PaperWarmStep(state, name, true);
}

void BM_PaperWarmNoPredictor(benchmark::State& state, const std::string& name) {
  PaperWarmStep(state, name, false, false);
}

// Scene by scene (each built once, kept for its three rows): BM_PaperCold/chair, ...
const bool kPaperRowsRegistered = [] {
  for (const char* scene : {"chair", "shoe", "mouse"}) {
    const std::string suffix = std::string("/") + scene;
    benchmark::RegisterBenchmark(("BM_PaperCold" + suffix).c_str(), BM_PaperCold, scene)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("BM_PaperWarm" + suffix).c_str(), BM_PaperWarm, scene)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("BM_PaperGradient" + suffix).c_str(), BM_PaperGradient, scene)
        ->Unit(benchmark::kSecond)
        ->Iterations(1)
        ->UseManualTime();
    benchmark::RegisterBenchmark(("BM_PaperWarmNoPredictor" + suffix).c_str(),
                                 BM_PaperWarmNoPredictor, scene)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
