// The cotangent stiffness K: symmetric, rows summing to zero, positive semi-definite (also
// with obtuse triangles, where single cotangent weights turn negative), its energy xᵀKx the
// exact Dirichlet energy ∫|∇x|² of a linear field on any triangle mesh, and convergent for
// smooth fields on a plane and on the sphere.
#include "ergo/mesh/cotangent_stiffness.h"

#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/flat_grid.h"

namespace ergo {
namespace {

// An icosphere with every vertex moved randomly by up to 30 % of the edge length: irregular,
// with obtuse triangles.
TriMesh JitteredIcosphere(int subdivisions, unsigned seed) {
  TriMesh mesh = MakeIcosphere(1.0, subdivisions);
  const double edge =
      (mesh.vertices.row(mesh.triangles(0, 0)) - mesh.vertices.row(mesh.triangles(0, 1))).norm();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-0.3 * edge, 0.3 * edge);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) mesh.vertices(v, k) += uniform(rng);
  return mesh;
}

// A flat grid whose interior vertices are moved randomly in the plane by up to 30 % of the
// spacing.
TriMesh JitteredFlatGrid(int cells, unsigned seed) {
  TriMesh mesh = testing::MakeFlatGrid(0.5, cells);
  const double spacing = 1.0 / cells;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-0.3 * spacing, 0.3 * spacing);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const Eigen::Vector3d p = mesh.vertices.row(v);
    if (std::abs(p.x()) < 0.5 - 1e-9 && std::abs(p.z()) < 0.5 - 1e-9) {
      mesh.vertices(v, 0) += uniform(rng);
      mesh.vertices(v, 2) += uniform(rng);
    }
  }
  return mesh;
}

bool HasAnObtuseAngle(const TriMesh& mesh) {
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = mesh.vertices.row(mesh.triangles(f, k));
      const Eigen::Vector3d q = mesh.vertices.row(mesh.triangles(f, (k + 1) % 3));
      const Eigen::Vector3d r = mesh.vertices.row(mesh.triangles(f, (k + 2) % 3));
      if ((q - p).dot(r - p) < 0) return true;
    }
  }
  return false;
}

TEST(Mesh, CotangentStiffnessIsSymmetricWithRowsSummingToZero) {
  for (const TriMesh& mesh : {JitteredIcosphere(2, 1), JitteredFlatGrid(6, 2),
                              MakeBox({0, 0, 0}, {0.5, 0.2, 0.4}, {5, 3, 4})}) {
    const SparseMatrix K = CotangentStiffness(mesh.triangles, mesh.vertices);
    const Eigen::MatrixXd dense = K;
    const double scale = dense.cwiseAbs().maxCoeff();
    // Round-off only: each entry is a sum of a few cotangents of size ~scale.
    EXPECT_LT((dense - dense.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
    EXPECT_LT((K * Eigen::VectorXd::Ones(K.cols())).cwiseAbs().maxCoeff(), 1e-13 * scale);
  }
}

TEST(Mesh, CotangentStiffnessIsPositiveSemidefiniteWithObtuseTriangles) {
  for (const TriMesh& mesh : {JitteredIcosphere(2, 3), JitteredFlatGrid(8, 4)}) {
    ASSERT_TRUE(HasAnObtuseAngle(mesh));  // else the check below proves less
    const Eigen::MatrixXd K = CotangentStiffness(mesh.triangles, mesh.vertices);
    // Some cotangent weights −K_ij are negative (obtuse opposite angles): PSD is not
    // just diagonal dominance here.
    EXPECT_GT(K.maxCoeff(), 0.0);
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    const double largest = eigenvalues.maxCoeff();
    // One zero eigenvalue (the constants of a connected mesh), the rest positive; the zero is
    // computed to about machine epsilon times the largest.
    EXPECT_GT(eigenvalues[0], -1e-12 * largest);
    EXPECT_LT(std::abs(eigenvalues[0]), 1e-12 * largest);
    EXPECT_GT(eigenvalues[1], 1e-6 * largest);
  }
}

TEST(Mesh, CotangentStiffnessIgnoresDegenerateTrianglesAndIsolatedVertices) {
  // The unit square (two triangles), a sliver triangle with three collinear corners glued to
  // its edge 1–2, and vertex 5 in no triangle.
  TriMesh mesh;
  mesh.vertices.resize(6, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0.5, 0, 3, 3, 3;
  mesh.triangles.resize(3, 3);
  mesh.triangles << 0, 1, 2, 0, 2, 3, 1, 4, 2;
  const Eigen::MatrixXd K = CotangentStiffness(mesh.triangles, mesh.vertices);
  ASSERT_TRUE(K.allFinite());
  Triangles square(2, 3);
  square << 0, 1, 2, 0, 2, 3;
  const Eigen::MatrixXd expected = CotangentStiffness(square, mesh.vertices);
  EXPECT_EQ(K, expected);
  EXPECT_EQ(K.row(5).cwiseAbs().sum() + K.row(4).cwiseAbs().sum(), 0.0);
  // Two right triangles sharing the diagonal 0–2: the edges have weight 1/2·cot 45° = 1/2
  // each (the right angles give the diagonal cot 90° = 0).
  EXPECT_DOUBLE_EQ(K(0, 1), -0.5);
  EXPECT_NEAR(K(0, 2), 0.0, 1e-16);
  EXPECT_DOUBLE_EQ(K(0, 0), 1.0);
}

// ∫|∇_s f|² of f(p) = a·p over flat triangles: per triangle, area · |a − (a·n)n|².
double LinearFieldEnergy(const TriMesh& mesh, const Eigen::Vector3d& a) {
  double energy = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d p = mesh.vertices.row(mesh.triangles(f, 0));
    const Eigen::Vector3d q = mesh.vertices.row(mesh.triangles(f, 1));
    const Eigen::Vector3d r = mesh.vertices.row(mesh.triangles(f, 2));
    const Eigen::Vector3d cross = (q - p).cross(r - p);
    const Eigen::Vector3d n = cross.normalized();
    energy += 0.5 * cross.norm() * (a - a.dot(n) * n).squaredNorm();
  }
  return energy;
}

TEST(Mesh, CotangentEnergyOfALinearFieldIsTheExactDirichletEnergy) {
  const Eigen::Vector3d a(0.3, -1.2, 0.7);
  for (const TriMesh& mesh : {JitteredIcosphere(2, 5), JitteredFlatGrid(7, 6),
                              MakeBox({0, 0, 0}, {0.5, 0.2, 0.4}, {5, 3, 4})}) {
    const SparseMatrix K = CotangentStiffness(mesh.triangles, mesh.vertices);
    const Eigen::VectorXd f = mesh.vertices * a;
    const double expected = LinearFieldEnergy(mesh, a);
    // A linear field is in the P1 space, so the only error is round-off.
    EXPECT_NEAR(f.dot(K * f), expected, 1e-12 * expected);
  }
}

TEST(Mesh, CotangentEnergyConvergesForSmoothFields) {
  // f = sin(πx) sin(πz) on the unit square: ∫|∇f|² = π²/2. P1 interpolation converges at
  // O(h²), so halving h should cut the error about 4× (we ask 3×).
  double previous = 0;
  for (int cells : {4, 8, 16, 32}) {
    TriMesh mesh = testing::MakeFlatGrid(0.5, cells);
    Eigen::VectorXd f(mesh.vertices.rows());
    for (Eigen::Index v = 0; v < f.size(); ++v)
      f[v] = std::sin(M_PI * (mesh.vertices(v, 0) + 0.5)) *
             std::sin(M_PI * (mesh.vertices(v, 2) + 0.5));
    const double error =
        std::abs(f.dot(CotangentStiffness(mesh.triangles, mesh.vertices) * f) - M_PI * M_PI / 2);
    std::cout << "square, " << cells << " cells: |error| " << error << "\n";
    if (previous > 0) {
      EXPECT_LT(error, previous / 3);
    }
    previous = error;
  }
  // f = xz on the unit sphere (a degree-2 spherical harmonic, −Δ_s f = 6f): ∫|∇_s f|² =
  // 6 ∫f² = 8π/5. The error comes from both the field and the polyhedral sphere.
  previous = 0;
  for (int subdivisions : {1, 2, 3, 4}) {
    const TriMesh mesh = MakeIcosphere(1.0, subdivisions);
    const Eigen::VectorXd f = mesh.vertices.col(0).cwiseProduct(mesh.vertices.col(2));
    const double error =
        std::abs(f.dot(CotangentStiffness(mesh.triangles, mesh.vertices) * f) - 8 * M_PI / 5);
    std::cout << "sphere, " << subdivisions << " subdivisions: |error| " << error << "\n";
    if (previous > 0) {
      EXPECT_LT(error, previous / 3);
    }
    previous = error;
  }
}

}  // namespace
}  // namespace ergo
