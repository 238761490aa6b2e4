// One design evaluation (φ and ∇φ) of a soft ball on a bumpy plate at about 2k and 10k body
// vertices: the warm equilibrium solve after a small design step, and the gradient part
// (exact K̂ assembly at y*, one factorisation, one adjoint solve, the cross terms). The
// issue's target: the gradient costs at most 40 % of the warm solve.
//   build/bin/design_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "ergo/design/design_problem.h"
#include "problems/bump_scenario.h"

namespace ergo {
namespace {

double EdgeLengthFor(int thousands) { return thousands <= 2 ? 0.0097 : 0.0057; }

struct Fixture {
  Scenario scenario;
  std::unique_ptr<DesignProblem> problem;
  Eigen::VectorXd x0, step;
};

Fixture& FixtureFor(int thousands) {
  static std::map<int, Fixture> cache;
  Fixture& f = cache[thousands];
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
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  DesignEvaluation e;
  int k = 0;
  for (auto _ : state) {
    // A new design each time (0.1 mm further along −∇φ): a genuine warm re-solve.
    e = f.problem->Evaluate(f.x0 + (++k) * f.step, true);
  }
  state.counters["vertices"] = static_cast<double>(f.scenario.body->rest().vertices.rows());
  state.counters["warm_solve_s"] = e.equilibrium.total_seconds;
  state.counters["gradient_s"] = e.timing.adjoint_seconds;
  state.counters["gradient_over_solve"] = e.timing.adjoint_seconds / e.equilibrium.total_seconds;
  state.counters["newton_iterations"] = e.equilibrium.iterations;
  state.counters["ok"] = e.ok ? 1 : 0;
}

BENCHMARK(BM_DesignEvaluationWithGradient)
    ->Arg(2)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(4);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
