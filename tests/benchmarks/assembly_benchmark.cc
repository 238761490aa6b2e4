// Full assembly of the body's reduced energy, gradient and Hessian (elastic + gravity,
// coloured parallel scatter into the fixed pattern, lever-arm term) for soft-ball bodies of
// about 2k and 10k vertices, PSD-projected and exact, on 1 and 2 threads. Issue target:
// 10k vertices in under 50 ms on one core.
//   build/bin/assembly_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <map>
#include <memory>

#include <benchmark/benchmark.h>
#include <omp.h>

#include "ergo/body/core_lock.h"
#include "ergo/body/reduced_system.h"
#include "problems/bump_scenario.h"

namespace ergo {
namespace {

struct Fixture {
  std::unique_ptr<LayeredBody> body;
  std::unique_ptr<ReducedSystem> system;
  BodyState state;
  Vertices positions;
};

Fixture& FixtureFor(int thousands) {
  static std::map<int, Fixture> cache;
  Fixture& f = cache[thousands];
  if (f.body) return f;
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");  // all rotations free: the lever-arm term is on
  f.body = std::make_unique<LayeredBody>(MakeSoftBall(
      0.05, 0.03, 1e4, 0.45, thousands <= 2 ? 0.0097 : 0.0057, Eigen::Vector3d::Zero(), options));
  f.system = std::make_unique<ReducedSystem>(*f.body);
  // A squashed state: every free vertex pushed 2 % towards y = 0 (compressed tissue).
  f.state = RestState(*f.body);
  const Vertices& rest = f.body->rest().vertices;
  for (Eigen::Index i = 0; i < f.body->free_vertices().size(); ++i)
    f.state.free_displacement[3 * i + 1] = -0.02 * rest(f.body->free_vertices()[i], 1);
  f.positions = DeformedPositions(*f.body, f.state);
  return f;
}

void Assemble(benchmark::State& state, HessianKind kind) {
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  const int threads = static_cast<int>(state.range(1));
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  ReducedSystem::Evaluation e;
  for (auto _ : state) {
    f.system->Evaluate(f.state, f.positions, kind, true, &e);
    benchmark::DoNotOptimize(f.system->Finalize(f.state, f.positions, kind, &e));
  }
  omp_set_num_threads(saved);
  state.counters["vertices"] = static_cast<double>(f.body->rest().vertices.rows());
  state.counters["tets"] = static_cast<double>(f.body->rest().tets.rows());
  state.counters["nonzeros"] = static_cast<double>(f.system->pattern().nonZeros());
  state.counters["colours"] = f.system->colour_count();
}

void BM_AssembleProjected(benchmark::State& state) { Assemble(state, HessianKind::kProjectedPsd); }
void BM_AssembleExact(benchmark::State& state) { Assemble(state, HessianKind::kExact); }

void BM_EnergyOnly(benchmark::State& state) {
  Fixture& f = FixtureFor(static_cast<int>(state.range(0)));
  const int saved = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(f.system->Energy(f.state, f.positions));
  omp_set_num_threads(saved);
  state.counters["vertices"] = static_cast<double>(f.body->rest().vertices.rows());
}

BENCHMARK(BM_AssembleProjected)
    ->Args({2, 1})
    ->Args({10, 1})
    ->Args({10, 2})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AssembleExact)->Args({10, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EnergyOnly)->Args({10, 1})->Args({10, 2})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
