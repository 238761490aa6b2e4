// Areas, normals, umbrella Laplacian and Taubin smoothing against values computed by hand.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

// Unit square in the xy plane split along the diagonal 0-2: two right triangles of area 1/2.
TriMesh UnitSquare() {
  TriMesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  mesh.triangles.resize(2, 3);
  mesh.triangles << 0, 1, 2, 0, 2, 3;
  return mesh;
}

// Regular octahedron with vertices at ±e_k: every vertex has four neighbours whose mean is 0.
TriMesh Octahedron() {
  TriMesh mesh;
  mesh.vertices.resize(6, 3);
  mesh.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  mesh.triangles.resize(8, 3);
  mesh.triangles << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  return mesh;
}

TEST(Mesh, BarycentricAreasOfTheUnitSquareAreHandComputed) {
  // Vertices 0 and 2 touch both triangles: 2 * (1/2)/3 = 1/3; vertices 1 and 3: 1/6.
  const Eigen::VectorXd areas = BarycentricVertexAreas(UnitSquare());
  EXPECT_DOUBLE_EQ(areas[0], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(areas[1], 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(areas[2], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(areas[3], 1.0 / 6.0);
}

TEST(Mesh, BarycentricAreasSumToTheSurfaceArea) {
  const TriMesh box = MakeBox({0, 0, 0}, {0.5, 0.2, 0.4}, {5, 3, 4});
  const double total = 2 * (0.5 * 0.2 + 0.2 * 0.4 + 0.5 * 0.4);
  EXPECT_NEAR(BarycentricVertexAreas(box).sum(), total, 1e-14);
}

TEST(Mesh, TriangleAreaGradientMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(9);
    for (int i = 0; i < 9; ++i) x[i] = uniform(rng);
    auto area = [](const Eigen::VectorXd& p) {
      return 0.5 *
             (p.segment<3>(3) - p.segment<3>(0)).cross(p.segment<3>(6) - p.segment<3>(0)).norm();
    };
    const Eigen::Matrix3d g =
        TriangleAreaGradient(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6));
    Eigen::VectorXd gradient(9);
    for (int k = 0; k < 3; ++k) gradient.segment<3>(3 * k) = g.row(k).transpose();
    std::string report;
    // Area is a smooth function away from degenerate triangles; central differences reach
    // ~1e-10 here, so 1e-7 leaves margin for the random geometry.
    const double error = testing::WorstGradientError(
        area, gradient, x, 1e-3, testing::StepSweep(1e-3, 5), 4, 9, trial, &report);
    EXPECT_LT(error, 1e-7) << report;
  }
}

TEST(Mesh, VertexNormalsOfABoxFaceCentreAreAxisAligned) {
  const TriMesh box = MakeBox({-1, -1, -1}, {1, 1, 1}, {2, 2, 2});
  const Vertices normals = VertexNormals(box);
  for (Eigen::Index v = 0; v < box.vertices.rows(); ++v) {
    const Eigen::Vector3d p = box.vertices.row(v);
    // Face centres are the lattice points with exactly one coordinate at ±1.
    if ((p.array().abs() > 0.5).count() == 1) {
      Eigen::Index axis;
      p.cwiseAbs().maxCoeff(&axis);
      EXPECT_NEAR(normals(v, axis), p[axis] > 0 ? 1.0 : -1.0, 1e-15);
    }
  }
}

TEST(Mesh, VertexNormalsOfASpherePointOutward) {
  const TriMesh sphere = MakeIcosphere(1.0, 3);
  const Vertices normals = VertexNormals(sphere);
  for (Eigen::Index v = 0; v < sphere.vertices.rows(); ++v) {
    // Radial to within the discretisation (edge length ~0.15 rad here).
    EXPECT_GT(normals.row(v).dot(sphere.vertices.row(v)), 0.999);
  }
}

TEST(Mesh, UmbrellaLaplacianOfTheUnitSquareIsHandComputed) {
  // Edges: 01 12 20 23 30. Degrees: v0 3 (1,2,3), v1 2 (0,2), v2 3 (0,1,3), v3 2 (0,2).
  const Eigen::MatrixXd L = Eigen::MatrixXd(UmbrellaLaplacian(UnitSquare().triangles, 4));
  Eigen::MatrixXd expected(4, 4);
  expected << 1, -1. / 3, -1. / 3, -1. / 3,  //
      -0.5, 1, -0.5, 0,                      //
      -1. / 3, -1. / 3, 1, -1. / 3,          //
      -0.5, 0, -0.5, 1;
  EXPECT_LT((L - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Mesh, UmbrellaLaplacianIgnoresIsolatedVertices) {
  TriMesh mesh = UnitSquare();
  mesh.vertices.conservativeResize(5, 3);
  mesh.vertices.row(4) << 7, 7, 7;
  const SparseMatrix L = UmbrellaLaplacian(mesh.triangles, 5);
  const Eigen::VectorXd values = Eigen::VectorXd::LinSpaced(5, 1, 5);
  EXPECT_EQ((L * values)[4], 0.0);  // the isolated vertex averages to itself
}

TEST(Mesh, TaubinIterationScalesTheOctahedronByHandComputedFactor) {
  // The 1-ring mean of every octahedron vertex is the origin, so L x = x and one Taubin
  // iteration multiplies positions by (1 − μ)(1 − λ) = 1.53 · 0.5 = 0.765.
  const TriMesh octahedron = Octahedron();
  const TriMesh once = TaubinSmooth(octahedron, {0.5, -0.53, 1});
  EXPECT_LT((once.vertices - 0.765 * octahedron.vertices).cwiseAbs().maxCoeff(), 1e-15);
  const TriMesh thrice = TaubinSmooth(octahedron, {0.5, -0.53, 3});
  EXPECT_LT((thrice.vertices - std::pow(0.765, 3) * octahedron.vertices).cwiseAbs().maxCoeff(),
            1e-15);
}

TEST(Mesh, TaubinOperatorAndItsTransposeAgreeWithTheExplicitMatrix) {
  const TriMesh sphere = MakeIcosphere(1.0, 1);
  const SparseMatrix L = UmbrellaLaplacian(sphere.triangles, sphere.vertices.rows());
  const Eigen::MatrixXd T = Eigen::MatrixXd(TaubinOperator(L, 0.5, -0.53));
  const TaubinParameters parameters{0.5, -0.53, 3};
  const Eigen::MatrixXd T3 = T * T * T;
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(sphere.vertices.rows(), 3);
  EXPECT_LT((ApplyTaubin(L, parameters, X) - T3 * X).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((ApplyTaubinTransposed(L, parameters, X) - T3.transpose() * X).cwiseAbs().maxCoeff(),
            1e-13);
}

TEST(Mesh, TaubinSmoothingKeepsFixedVertices) {
  const TriMesh octahedron = Octahedron();
  std::vector<bool> fixed(6, false);
  fixed[0] = true;
  const TriMesh smoothed = TaubinSmooth(octahedron, {0.5, -0.53, 2}, fixed);
  EXPECT_EQ(smoothed.vertices.row(0), octahedron.vertices.row(0));
  EXPECT_NE(smoothed.vertices.row(1), octahedron.vertices.row(1));
}

}  // namespace
}  // namespace ergo
