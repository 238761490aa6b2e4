// The linearly precise Laplacian vanishes on linear fields (the classic −K does not at the
// boundary); the biharmonic weights built on it reproduce linear functions exactly from
// scattered handles on irregular planar meshes, interpolate their handles, keep constants on
// curved surfaces, and refuse handle layouts that cannot determine a field.
#include "ergo/ergonomics/biharmonic_interpolation.h"

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/ergonomics/linearly_precise_laplacian.h"
#include "ergo/mesh/cotangent_stiffness.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/flat_grid.h"

namespace ergo {
namespace {

// A flat grid (xz plane) whose interior vertices are moved at random by up to a fifth of the
// spacing along x and z: irregular triangles that never fold over (a corner is 0.71 spacings
// from the opposite diagonal, and the three corners together move it by at most 0.57).
TriMesh JitteredGrid(double half_width, int cells, unsigned seed) {
  TriMesh mesh = testing::MakeFlatGrid(half_width, cells);
  std::mt19937 random(seed);
  const double spacing = 2 * half_width / cells;
  std::uniform_real_distribution<double> jitter(-spacing / 5, spacing / 5);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const bool boundary = std::abs(std::abs(mesh.vertices(v, 0)) - half_width) < 1e-12 ||
                          std::abs(std::abs(mesh.vertices(v, 2)) - half_width) < 1e-12;
    if (boundary) continue;
    mesh.vertices(v, 0) += jitter(random);
    mesh.vertices(v, 2) += jitter(random);
  }
  return mesh;
}

// The triangles whose centroid satisfies `keep`, with unused vertices dropped.
TriMesh KeepTriangles(const TriMesh& mesh,
                      const std::function<bool(const Eigen::Vector3d&)>& keep) {
  std::vector<int> local(static_cast<size_t>(mesh.vertices.rows()), -1);
  std::vector<Eigen::Vector3i> triangles;
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centroid += mesh.vertices.row(mesh.triangles(f, k)).transpose() / 3;
    if (!keep(centroid)) continue;
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      if (local[v] < 0) {
        local[v] = static_cast<int>(vertices.size());
        vertices.push_back(mesh.vertices.row(v).transpose());
      }
      t[k] = local[v];
    }
    triangles.push_back(t);
  }
  TriMesh kept;
  kept.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i)
    kept.vertices.row(static_cast<Eigen::Index>(i)) = vertices[i].transpose();
  kept.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t f = 0; f < triangles.size(); ++f)
    kept.triangles.row(static_cast<Eigen::Index>(f)) = triangles[f].transpose();
  return kept;
}

// `count` handles at random points of random triangles.
std::vector<SurfacePoint> RandomHandles(const TriMesh& mesh, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> triangle(0, static_cast<int>(mesh.triangles.rows()) - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurfacePoint> handles;
  for (int j = 0; j < count; ++j) {
    double a = unit(random), b = unit(random);
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    handles.push_back(SurfacePoint{triangle(random), Eigen::Vector3d(1 - a - b, a, b)});
  }
  return handles;
}

Eigen::Vector3d PointOf(const TriMesh& mesh, const SurfacePoint& handle) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    p += handle.barycentric[k] * mesh.vertices.row(mesh.triangles(handle.triangle, k)).transpose();
  return p;
}

// u = 3 + 40 x − 25 z (any linear field; metres in, dimensionless out).
double Linear(const Eigen::Vector3d& p) { return 3 + 40 * p.x() - 25 * p.z(); }

// The largest error of the interpolant of Linear sampled at the handles, over the vertices,
// relative to the field's range on the mesh.
double LinearReproductionError(const TriMesh& mesh, const std::vector<SurfacePoint>& handles,
                               const BiharmonicOptions& options) {
  const BiharmonicWeights weights = ComputeBiharmonicWeights(mesh, handles, options);
  EXPECT_TRUE(weights.ok) << weights.message;
  if (!weights.ok) return 1;
  Eigen::VectorXd values(static_cast<Eigen::Index>(handles.size()));
  for (size_t j = 0; j < handles.size(); ++j)
    values[static_cast<Eigen::Index>(j)] = Linear(PointOf(mesh, handles[j]));
  const Eigen::VectorXd u = weights.Interpolate(values);
  double error = 0, low = 1e300, high = -1e300;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const double exact = Linear(mesh.vertices.row(v).transpose());
    error = std::max(error, std::abs(u[v] - exact));
    low = std::min(low, exact);
    high = std::max(high, exact);
  }
  return error / (high - low);
}

Eigen::VectorXd LinearAtVertices(const TriMesh& mesh) {
  Eigen::VectorXd u(mesh.vertices.rows());
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    u[v] = Linear(mesh.vertices.row(v).transpose());
  return u;
}

// Σ_T ∫_T ∇φ_i = ∮ φ_i n holds exactly for P1 elements on a planar mesh, so L̃u = 0 to
// round-off (the entries are O(1), the field O(10): 1e-12 leaves a factor 100 to spare).
TEST(ErgonomicsBiharmonic, LinearlyPreciseLaplacianVanishesOnLinearFields) {
  const TriMesh mesh = JitteredGrid(0.1, 12, 7);
  const Eigen::VectorXd u = LinearAtVertices(mesh);
  const Eigen::VectorXd precise = LinearlyPreciseLaplacian(mesh) * u;
  EXPECT_LT(precise.cwiseAbs().maxCoeff(), 1e-12 * u.cwiseAbs().maxCoeff());
  // The classic Laplacian drops the boundary flux: at the boundary it sees the linear field's
  // normal derivative (here O(1) on edges of about 17 mm).
  const Eigen::VectorXd classic = CotangentStiffness(mesh.triangles, mesh.vertices) * u;
  EXPECT_GT(classic.cwiseAbs().maxCoeff(), 0.1);
}

// The weights reproduce a linear field sampled at scattered handles to round-off, on a
// jittered square, a jittered L shape (a re-entrant corner) and a coarse square with few
// handles. The zero-Neumann bi-Laplacian misses by percent on the same layouts.
TEST(ErgonomicsBiharmonic, ReproducesLinearFunctionsExactly) {
  const TriMesh square = JitteredGrid(0.1, 16, 3);
  const TriMesh l_shape = KeepTriangles(
      JitteredGrid(0.1, 16, 5), [](const Eigen::Vector3d& c) { return c.x() < 0 || c.z() < 0; });
  const TriMesh coarse = testing::MakeFlatGrid(0.05, 4);
  struct Case {
    const char* name;
    const TriMesh* mesh;
    int handles;
  } cases[] = {{"square", &square, 40}, {"L shape", &l_shape, 30}, {"coarse square", &coarse, 3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::vector<SurfacePoint> handles = RandomHandles(*c.mesh, c.handles, 11);
    // Round-off of the factorisation and of S⁻¹ on O(1e4)-conditioned systems: 1e-8.
    EXPECT_LT(LinearReproductionError(*c.mesh, handles, BiharmonicOptions{true}), 1e-8);
    if (c.handles > 3) {
      EXPECT_GT(LinearReproductionError(*c.mesh, handles, BiharmonicOptions{false}), 1e-3)
          << "the zero-Neumann bi-Laplacian should not be linearly precise";
    }
  }
}

// B W = I: the field passes through every handle's value, wherever in its triangle it sits.
TEST(ErgonomicsBiharmonic, InterpolatesTheHandles) {
  const TriMesh mesh = JitteredGrid(0.1, 14, 9);
  const std::vector<SurfacePoint> handles = RandomHandles(mesh, 25, 4);
  const BiharmonicWeights weights = ComputeBiharmonicWeights(mesh, handles);
  ASSERT_TRUE(weights.ok) << weights.message;
  std::mt19937 random(2);
  std::uniform_real_distribution<double> value(0, 200e3);
  Eigen::VectorXd values(25);
  for (Eigen::Index j = 0; j < 25; ++j) values[j] = value(random);
  const Eigen::VectorXd u = weights.Interpolate(values);
  for (size_t j = 0; j < handles.size(); ++j) {
    double at_handle = 0;
    for (int k = 0; k < 3; ++k)
      at_handle += handles[j].barycentric[k] * u[mesh.triangles(handles[j].triangle, k)];
    EXPECT_NEAR(at_handle, values[static_cast<Eigen::Index>(j)], 1e-8 * 200e3) << "handle " << j;
  }
}

// On a curved, closed surface constants are still reproduced (E vanishes on them): the
// weights of every vertex sum to one.
TEST(ErgonomicsBiharmonic, WeightsSumToOneOnACurvedSurface) {
  const TriMesh sphere = MakeIcosphere(0.05, 2);
  const BiharmonicWeights weights = ComputeBiharmonicWeights(sphere, RandomHandles(sphere, 12, 8));
  ASSERT_TRUE(weights.ok) << weights.message;
  const Eigen::VectorXd sums = weights.weights.rowwise().sum();
  EXPECT_LT((sums.array() - 1).abs().maxCoeff(), 1e-8);
}

TEST(ErgonomicsBiharmonic, RefusesLayoutsThatCannotDetermineAField) {
  const TriMesh mesh = testing::MakeFlatGrid(0.1, 8);
  // Two handles.
  BiharmonicWeights weights = ComputeBiharmonicWeights(mesh, RandomHandles(mesh, 2, 1));
  EXPECT_FALSE(weights.ok);
  EXPECT_NE(weights.message.find("fewer than three"), std::string::npos) << weights.message;
  // Five handles on the line z = x (the grid's diagonals a–d run along it).
  std::vector<SurfacePoint> on_a_line;
  for (int k = 0; k < 5; ++k) {
    // Corner a of cell (k, k): the grid point (k, k), on the line z = x.
    on_a_line.push_back(SurfacePoint{2 * (k * 8 + k), Eigen::Vector3d(1, 0, 0)});
  }
  weights = ComputeBiharmonicWeights(mesh, on_a_line);
  EXPECT_FALSE(weights.ok);
  EXPECT_NE(weights.message.find("one line"), std::string::npos) << weights.message;
  // Two of four handles at one point.
  std::vector<SurfacePoint> twice = RandomHandles(mesh, 4, 3);
  twice.push_back(twice[1]);
  weights = ComputeBiharmonicWeights(mesh, twice);
  EXPECT_FALSE(weights.ok);
  EXPECT_NE(weights.message.find("coincide"), std::string::npos) << weights.message;
  // A surface of two separate squares with every handle on one of them.
  const TriMesh two = KeepTriangles(testing::MakeFlatGrid(0.1, 8), [](const Eigen::Vector3d& c) {
    return std::abs(c.x()) > 0.03;
  });
  std::vector<SurfacePoint> one_side;
  for (const SurfacePoint& h : RandomHandles(two, 40, 5))
    if (PointOf(two, h).x() < 0) one_side.push_back(h);
  weights = ComputeBiharmonicWeights(two, one_side);
  EXPECT_FALSE(weights.ok);
  EXPECT_NE(weights.message.find("holds 0 handles"), std::string::npos) << weights.message;
}

}  // namespace
}  // namespace ergo
