// Static equilibrium of a soft ball (a tissue layer around a rigid core, built by the body
// builder) resting on a flat slab: cold solves from 1 mm above, warm solves after the slab
// rises by 0.1 mm, at about 2k, 10k and 40k body vertices, with the time split (assembly,
// contact, factorisation, solves, line search) and Newton iteration counts; and Newton against
// Ceres L-BFGS to the same residual on the smallest body.
//   build/bin/equilibrium_benchmark --benchmark_repetitions=3
//   --benchmark_report_aggregates_only=true
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "ergo/body/core_lock.h"
#include "ergo/equilibrium/ceres_equilibrium.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/primitives.h"
#include "problems/bump_scenario.h"

namespace ergo {
namespace {

// Edge lengths giving ~2k, ~10k, ~40k vertices for a 5 cm ball with a 3 cm core.
double EdgeLengthFor(int thousands) {
  return thousands <= 2 ? 0.0097 : thousands <= 10 ? 0.0057 : 0.0036;
}

struct Fixture {
  std::unique_ptr<LayeredBody> body;
  std::unique_ptr<Support> slab, raised;
  BodyState start;
};

Fixture& FixtureFor(int thousands) {
  static std::map<int, Fixture> cache;
  Fixture& f = cache[thousands];
  if (f.body) return f;
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  f.body = std::make_unique<LayeredBody>(MakeSoftBall(
      0.05, 0.03, 1e4, 0.45, EdgeLengthFor(thousands), Eigen::Vector3d::Zero(), options));
  f.slab =
      std::make_unique<Support>(MakeBox({-0.15, -0.11, -0.15}, {0.15, -0.06, 0.15}, {2, 1, 2}));
  f.raised = std::make_unique<Support>(
      MakeBox({-0.15, -0.11, -0.15}, {0.15, -0.06 + 1e-4, 0.15}, {2, 1, 2}));
  f.start = PlaceAboveSupport(*f.body, RestState(*f.body), *f.slab, 1e-3).state;
  return f;
}

EquilibriumOptions Options() {
  EquilibriumOptions options;
  options.contact_stiffness = 1e7;  // κ, Pa/m: ≈ 0.3 mm penetration for this ball
  return options;
}

void Report(benchmark::State& state, const LayeredBody& body, const EquilibriumResult& r) {
  state.counters["vertices"] = static_cast<double>(body.rest().vertices.rows());
  state.counters["newton_iterations"] = r.iterations;
  state.counters["assembly_s"] = r.assembly_seconds;
  state.counters["contact_s"] = r.contact_seconds;
  state.counters["factorization_s"] = r.factorization_seconds;
  state.counters["solve_s"] = r.solve_seconds;
  state.counters["factorizations"] = r.factorizations;
  state.counters["line_search_s"] = r.line_search_seconds;
  state.counters["converged"] = r.converged ? 1 : 0;
}

void BM_ColdSolve(benchmark::State& state) {
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  EquilibriumSolver solver(*f.body, Options());
  EquilibriumResult result;
  for (auto _ : state) result = solver.Solve(*f.slab, f.start);
  Report(state, *f.body, result);
}

void BM_WarmSolveAfterTenthMillimetreChange(benchmark::State& state) {
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  EquilibriumSolver solver(*f.body, Options());
  const EquilibriumResult cold = solver.Solve(*f.slab, f.start);
  EquilibriumResult result;
  for (auto _ : state) result = solver.Solve(*f.raised, cold.state);
  Report(state, *f.body, result);
}

// Ceres L-BFGS from the same warm start, to the residual Newton reaches (1e-8 of the load).
void BM_WarmSolveCeresLbfgs(benchmark::State& state) {
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  EquilibriumSolver solver(*f.body, Options());
  const EquilibriumResult cold = solver.Solve(*f.slab, f.start);
  ceres::GradientProblemSolver::Options options;
  options.line_search_direction_type = ceres::LBFGS;
  options.max_num_iterations = 100000;
  options.function_tolerance = 0;
  options.parameter_tolerance = 0;
  options.gradient_tolerance = 1e-8 * f.body->TotalLoad().norm();  // max-norm of the gradient, N
  EquilibriumResult result;
  for (auto _ : state)
    result = SolveEquilibriumWithCeres(solver.potential(), *f.raised, cold.state, 1e-8, options);
  state.counters["vertices"] = static_cast<double>(f.body->rest().vertices.rows());
  state.counters["iterations"] = result.iterations;
  state.counters["relative_residual"] = result.relative_residual;
}

BENCHMARK(BM_ColdSolve)->Arg(2)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_WarmSolveAfterTenthMillimetreChange)
    ->Arg(2)
    ->Arg(10)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_WarmSolveCeresLbfgs)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
