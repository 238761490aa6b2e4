// CHOLMOD supernodal factorisation and solve on the graph Laplacian (+ a small shift, to
// make it positive definite) of a ~30k-vertex tetrahedral grid: the scalar problem, and
// the 3-DOF-per-vertex block version with the pattern of a 3D stiffness matrix.
//   build/bin/cholesky_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <set>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/sparse_cholesky.h"

namespace ergo {
namespace {

// Graph Laplacian of the tet edges + 1e-3·I, with `block` DOFs per vertex.
SparseCholesky::Matrix GridLaplacian(int block) {
  // 31 x 31 x 32 lattice points = 30,752 vertices.
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {1, 1, 1}, {30, 30, 31});
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index t = 0; t < grid.tets.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) edges.insert(std::minmax(grid.tets(t, a), grid.tets(t, b)));
  const auto n = static_cast<int>(grid.vertices.rows());
  std::vector<double> degree(n, 1e-3);
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& [a, b] : edges) {
    degree[a] += 1;
    degree[b] += 1;
    for (int k = 0; k < block; ++k) entries.emplace_back(block * a + k, block * b + k, -1.0);
  }
  for (int v = 0; v < n; ++v)
    for (int k = 0; k < block; ++k)
      for (int l = k; l < block; ++l)
        entries.emplace_back(block * v + k, block * v + l, k == l ? degree[v] : 0.1);
  SparseCholesky::Matrix upper(block * n, block * n);
  upper.setFromTriplets(entries.begin(), entries.end());
  upper.makeCompressed();
  return upper;
}

void BM_Analyze(benchmark::State& state) {
  const auto matrix = GridLaplacian(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    SparseCholesky cholesky;
    cholesky.Analyze(matrix);
    benchmark::DoNotOptimize(cholesky.analyzed());
  }
  state.counters["dofs"] = static_cast<double>(matrix.rows());
}

void BM_Factorize(benchmark::State& state) {
  const auto matrix = GridLaplacian(static_cast<int>(state.range(0)));
  SparseCholesky cholesky;
  cholesky.Analyze(matrix);
  for (auto _ : state) benchmark::DoNotOptimize(cholesky.Factorize(matrix).ok);
  state.counters["dofs"] = static_cast<double>(matrix.rows());
}

void BM_Solve(benchmark::State& state) {
  const auto matrix = GridLaplacian(static_cast<int>(state.range(0)));
  SparseCholesky cholesky;
  cholesky.Analyze(matrix);
  cholesky.Factorize(matrix);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  for (auto _ : state) benchmark::DoNotOptimize(cholesky.Solve(rhs));
  state.counters["dofs"] = static_cast<double>(matrix.rows());
}

BENCHMARK(BM_Analyze)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Factorize)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
