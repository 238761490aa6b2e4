// How a warm design evaluation (φ + ∇φ) scales with the body's and the support's size, on
// the paper chair (problems/chair_scenario.h, FromPreset("paper"), γ = 0 as the flagfile):
//
//   BM_WarmEvaluationScaling/body=B/support=S
//     the body's tet edge and the block's top spacing chosen for about B and S thousand
//     vertices (body 2k, 10k, 40k at the paper support; support 10k, 40k, 160k at the paper
//     body). The scene is built and evaluated cold once (not timed), then one warm evaluation
//     after a typical optimiser step (the filtered design along −∇φ, largest support move
//     0.2 mm; followed, tangent predictor) is timed. Counters: the warm evaluation's split
//     (ergo/design/evaluation_timing.h), the sizes, and `one_factorization_s` — the cold
//     evaluation's factorisation time per factorisation, the yardstick for the body size.
//
//   build/bin/scaling_benchmark --benchmark_out=scaling.json --benchmark_out_format=json
//   tools/plot_scaling.py scaling.json scaling.png   # table, fitted exponents, log-log plot
//
// The 40k body takes minutes to mesh and to solve cold; the whole run takes about 15–25
// minutes on 2 cores. Diagnostics, set in the environment: ERGO_TRACE_NEWTON=1 prints every
// Newton iteration (residual N, step η, contact vertices, the active set's changes) to stderr;
// ERGO_NO_REUSE=1 refactorises at every Newton iteration (no PCG on an old factor);
// ERGO_NO_PREDICTOR=1 starts the warm solve without the tangent predictor.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "ergo/design/design_problem.h"
#include "problems/chair_scenario.h"
#include "tests/benchmarks/evaluation_counters.h"

namespace ergo {
namespace {

constexpr double kStep = 2e-4;  // m: the largest support vertex move of the warm step

// Body tet edge (m) for about `thousands` thousand body vertices: the chair's quick (0.035 m,
// 2.3k) and paper (0.019 m, 11.5k) presets, and 0.012 m (about 40k; vertices grow as
// edge^-2.6 between the two presets).
double BodyEdgeFor(int thousands) {
  if (thousands <= 2) return 0.035;
  if (thousands <= 10) return 0.019;
  return 0.012;
}

// The block's top spacing (m) for about `thousands` thousand support vertices: the paper's
// 3 mm gives 39.9k; the top grid's vertex count goes as spacing^-2.
double SupportSpacingFor(int thousands) {
  if (thousands <= 10) return 0.006;
  if (thousands <= 40) return 0.003;
  return 0.0015;
}

struct ScaledScene {
  Scenario scenario;
  std::unique_ptr<DesignProblem> after_cold;  // holds the cold equilibrium, factor and cache
  Eigen::VectorXd x0, step;
  double one_factorization_s = 0;
  bool ok = false;
};

ScaledScene& SceneFor(int body_thousands, int support_thousands) {
  static std::map<std::pair<int, int>, ScaledScene> cache;
  ScaledScene& s = cache[{body_thousands, support_thousands}];
  if (s.after_cold) return s;
  ChairScenarioOptions options = ChairScenarioOptions::FromPreset("paper");
  options.body_edge_length = BodyEdgeFor(body_thousands);
  options.block.top_spacing = SupportSpacingFor(support_thousands);
  s.scenario = MakeChairScenario(options);
  s.scenario.design.gamma = 0;  // the flagfile's (the filter keeps the design smooth)
  if (std::getenv("ERGO_NO_REUSE")) s.scenario.design.equilibrium.reuse_factorization = false;
  if (std::getenv("ERGO_NO_PREDICTOR")) s.scenario.design.tangent_predictor = false;
  if (std::getenv("ERGO_TRACE_NEWTON")) {
    s.scenario.design.equilibrium.progress = [](const NewtonIterationReport& r) {
      std::fprintf(stderr, "newton %d residual %.3e step %.3g contacts %d (+%d −%d, %d switched)\n",
                   r.iteration, r.residual, r.step, r.contact_vertices, r.contacts_entered,
                   r.contacts_left, r.feature_switches);
    };
  }
  s.after_cold = std::make_unique<DesignProblem>(s.scenario.MakeProblem());
  s.after_cold->set_placement(DesignPlacement::kFresh);
  s.x0 = s.after_cold->InitialDesign();
  const DesignEvaluation cold = s.after_cold->Evaluate(s.x0, true);
  s.ok = cold.ok;
  if (!s.ok) return s;
  s.after_cold->set_placement(DesignPlacement::kFollowed);
  const double largest = s.after_cold->parameterization().VertexMoves(cold.gradient).maxCoeff();
  s.step = -cold.gradient * (kStep / largest);
  if (cold.timing.factorizations > 0)
    s.one_factorization_s = cold.timing.factorization_seconds / cold.timing.factorizations;
  return s;
}

void BM_WarmEvaluationScaling(benchmark::State& state, int body_thousands, int support_thousands) {
  ScaledScene& s = SceneFor(body_thousands, support_thousands);
  if (!s.ok) {
    state.SkipWithError("the cold evaluation failed");
    return;
  }
  DesignEvaluation e;
  for (auto _ : state) {
    state.PauseTiming();
    DesignProblem problem(*s.after_cold);  // every iteration takes the same step
    state.ResumeTiming();
    e = problem.Evaluate(s.x0 + s.step, true);
  }
  ReportEvaluationCounters(state, s.scenario, e);
  state.counters["one_factorization_s"] = s.one_factorization_s;
}

const bool kScalingRowsRegistered = [] {
  const std::pair<int, int> rows[] = {{2, 40}, {10, 40}, {40, 40}, {10, 10}, {10, 160}};
  for (const auto& [body, support] : rows) {
    const std::string name = "BM_WarmEvaluationScaling/body=" + std::to_string(body) +
                             "k/support=" + std::to_string(support) + "k";
    benchmark::RegisterBenchmark(name.c_str(), BM_WarmEvaluationScaling, body, support)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
