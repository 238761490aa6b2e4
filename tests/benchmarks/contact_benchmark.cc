// Support queries against a 30k-triangle geodesic sphere (radius 0.25 m, class-I
// subdivision of an icosahedron, frequency 39: 30 420 triangles, edges ≈ 5 mm), single
// thread, queries within 5 mm of the surface (DESIGN §6's measurement setup):
//   - closest point, cold (no hint) in random order and in a spatially coherent order, and
//     with the previous anchor as hint (the query moved by ≤ 0.5 mm since);
//   - inside test (Contains) and Penetration (inside test + closest point);
//   - TrackPenetration for vertices moving ≤ 0.1 mm between calls (the DESIGN §6 shortcut);
//   - UpdateVertices (tree + pseudo-normal rebuild after the support moved).
// Run: contact_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <Eigen/Geometry>

#include "ergo/contact/support.h"
#include "ergo/mesh/primitives.h"

namespace ergo {
namespace {

constexpr double kRadius = 0.25;
constexpr int kFrequency = 39;  // 20 · 39² = 30 420 triangles
constexpr int kQueries = 1 << 16;

// Icosahedron faces split into frequency² triangles each, vertices shared along the
// icosahedron's edges (keyed by their integer barycentric weights), projected on the sphere.
TriMesh GeodesicSphere(double radius, int n) {
  const TriMesh ico = MakeIcosphere(1.0, 0);
  std::map<std::array<int, 6>, int> ids;  // sorted (vertex, weight) pairs -> id
  std::vector<Eigen::Vector3d> vertices;
  const auto vertex = [&](int f, int i, int j) {
    const int w[3] = {n - i - j, i, j};
    std::array<std::pair<int, int>, 3> terms;
    for (int c = 0; c < 3; ++c) terms[c] = {w[c] == 0 ? -1 : ico.triangles(f, c), w[c]};
    std::sort(terms.begin(), terms.end());
    const std::array<int, 6> key = {terms[0].first,  terms[0].second, terms[1].first,
                                    terms[1].second, terms[2].first,  terms[2].second};
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int c = 0; c < 3; ++c) x += w[c] * Eigen::Vector3d(ico.vertices.row(ico.triangles(f, c)));
    vertices.push_back(radius * x.normalized());
    const int id = static_cast<int>(vertices.size()) - 1;
    ids.emplace(key, id);
    return id;
  };
  std::vector<Eigen::Vector3i> triangles;
  for (int f = 0; f < ico.triangles.rows(); ++f) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        triangles.emplace_back(vertex(f, i, j), vertex(f, i + 1, j), vertex(f, i, j + 1));
        if (i + j + 1 < n) {
          triangles.emplace_back(vertex(f, i + 1, j), vertex(f, i + 1, j + 1), vertex(f, i, j + 1));
        }
      }
    }
  }
  TriMesh mesh;
  mesh.vertices.resize(vertices.size(), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v) mesh.vertices.row(v) = vertices[v];
  mesh.triangles.resize(triangles.size(), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) mesh.triangles.row(t) = triangles[t];
  return mesh;
}

const Support& Sphere() {
  static const Support support(GeodesicSphere(kRadius, kFrequency), "geodesic sphere");
  return support;
}

// Random directions, radial offsets uniform in ±5 mm.
const std::vector<Eigen::Vector3d>& Queries() {
  static const std::vector<Eigen::Vector3d> queries = [] {
    std::mt19937 rng(1);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> offset(-5e-3, 5e-3);
    std::vector<Eigen::Vector3d> q;
    for (int i = 0; i < kQueries; ++i) {
      const Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
      q.push_back((kRadius + offset(rng)) * d.normalized());
    }
    return q;
  }();
  return queries;
}

// The same queries in Morton (Z-curve) order: neighbours in sequence, as when the skin
// vertices of a body are visited in mesh order; the tree's upper levels stay in cache.
const std::vector<Eigen::Vector3d>& CoherentQueries() {
  static const std::vector<Eigen::Vector3d> queries = [] {
    const auto morton = [](const Eigen::Vector3d& x) {
      std::uint64_t code = 0;
      for (int axis = 0; axis < 3; ++axis) {
        const auto cell = static_cast<std::uint64_t>((x[axis] / kRadius + 1.1) / 2.2 * 1023);
        for (int bit = 0; bit < 10; ++bit) code |= ((cell >> bit) & 1) << (3 * bit + axis);
      }
      return code;
    };
    std::vector<Eigen::Vector3d> q = Queries();
    std::sort(q.begin(), q.end(), [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return morton(a) < morton(b);
    });
    return q;
  }();
  return queries;
}

void BM_ClosestPointCold(benchmark::State& state) {
  const Support& support = Sphere();
  const auto& queries = Queries();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(support.ClosestPoint(queries[i]));
    i = (i + 1) % queries.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["triangles"] = static_cast<double>(support.mesh().triangles.rows());
}
BENCHMARK(BM_ClosestPointCold);

void BM_ClosestPointColdCoherentOrder(benchmark::State& state) {
  const Support& support = Sphere();
  const auto& queries = CoherentQueries();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(support.ClosestPoint(queries[i]));
    i = (i + 1) % queries.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClosestPointColdCoherentOrder);

void BM_ClosestPointWithHint(benchmark::State& state) {
  const Support& support = Sphere();
  const auto& queries = Queries();
  // The previous answers, and the queries moved by up to 0.5 mm since.
  std::vector<SupportPoint> hints;
  std::vector<Eigen::Vector3d> moved;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> step(-0.5e-3 / std::sqrt(3.0), 0.5e-3 / std::sqrt(3.0));
  for (const auto& q : queries) {
    hints.push_back(support.ClosestPoint(q));
    moved.push_back(q + Eigen::Vector3d(step(rng), step(rng), step(rng)));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(support.ClosestPoint(moved[i], &hints[i]));
    i = (i + 1) % moved.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClosestPointWithHint);

void BM_InsideTest(benchmark::State& state) {
  const Support& support = Sphere();
  const auto& queries = Queries();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(support.Contains(queries[i]));
    i = (i + 1) % queries.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_InsideTest);

void BM_Penetration(benchmark::State& state) {
  const Support& support = Sphere();
  const auto& queries = Queries();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(support.Penetration(queries[i]));
    i = (i + 1) % queries.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Penetration);

// Skin vertices followed across Newton iterations: each visit moves a vertex by a random
// step of ≤ 0.1 mm and calls TrackPenetration with its tracked state; a vertex that stays
// within its distance of where it was last outside needs no search (DESIGN §6).
void BM_TrackPenetration(benchmark::State& state) {
  const Support& support = Sphere();
  std::vector<Eigen::Vector3d> position = Queries();
  std::vector<SupportPoint> track(position.size());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> step(-0.1e-3 / std::sqrt(3.0), 0.1e-3 / std::sqrt(3.0));
  std::vector<Eigen::Vector3d> steps(4096);
  for (auto& s : steps) s = Eigen::Vector3d(step(rng), step(rng), step(rng));
  std::size_t i = 0, k = 0;
  for (auto _ : state) {
    position[i] += steps[k];
    benchmark::DoNotOptimize(support.TrackPenetration(position[i], &track[i]));
    i = (i + 1) % position.size();
    k = (k + 1) % steps.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TrackPenetration);

void BM_UpdateVertices(benchmark::State& state) {
  Support support(GeodesicSphere(kRadius, kFrequency), "geodesic sphere");
  Vertices a = support.mesh().vertices, b = 1.001 * a;
  bool flip = false;
  for (auto _ : state) {
    support.UpdateVertices(flip ? a : b);
    flip = !flip;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_UpdateVertices)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
