// The spline design space (DesignParameterization::kSpline, ergo/design/spline_lattice.h):
// the lattice's weights form a non-negative partition of unity that reproduces linear fields
// exactly; the pull-back is the exact transpose of Positions (finite differences along
// random directions, the gradient's own direction and every coordinate) on a block whose
// top has a rounded front edge; the box for a move cap keeps every vertex within the cap;
// DesignFor projects onto the space; and the same controls move the designed square of a
// 10 mm and a 5 mm grid to the same surface, vertex for vertex.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/design/spline_lattice.h"
#include "ergo/design/support_parameterization.h"
#include "ergo/mesh/surface_geometry.h"
#include "problems/profile_block.h"
#include "tests/support/design_block.h"
#include "tests/support/finite_difference.h"
#include "tests/support/flat_grid.h"

namespace ergo {
namespace {

constexpr double kSpacing = 0.02;  // m: two top edges of the block below

Eigen::MatrixXd RandomPoints(int count, double extent, std::mt19937* rng) {
  std::uniform_real_distribution<double> uniform(-extent, extent);
  Eigen::MatrixXd points(count, 3);
  for (int p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c) points(p, c) = uniform(*rng);
  return points;
}

TEST(SplineLattice, CubicBSplineHasItsTextbookValues) {
  // N(0) = 2/3, N(±1) = 1/6, N(±2) = 0; N(1/2) = 23/48 (hand: 2/3 − 1/4 + 1/16).
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(0), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(1), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(-1), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(2), 0.0);
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(0.5), 23.0 / 48.0);
  EXPECT_DOUBLE_EQ(SplineLattice::CubicBSpline(-1.5), 1.0 / 48.0);
}

TEST(SplineLattice, WeightsAreANonNegativePartitionOfUnityThatReproducesLinearFields) {
  std::mt19937 rng(5);
  const Eigen::MatrixXd points = RandomPoints(300, 0.1, &rng);
  const SplineLattice lattice(points, 0.013, Eigen::Vector3d(-0.11, -0.105, -0.1));
  const Eigen::SparseMatrix<double>& B = lattice.basis();
  ASSERT_EQ(B.rows(), points.rows());
  EXPECT_GE(B.coeffs().minCoeff(), 0.0);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(B.cols());
  EXPECT_LT((B * ones - Eigen::VectorXd::Ones(B.rows())).lpNorm<Eigen::Infinity>(), 1e-14);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = B;
  for (int p = 0; p < rows.rows(); ++p) EXPECT_LE(rows.innerVector(p).nonZeros(), 64);
  // A linear field a·x + b given at the controls' positions comes back exactly at every point
  // (cubic B-splines reproduce linear functions); 1e-14 m is round-off on 0.1 m coordinates.
  const Eigen::Vector3d a(0.3, -1.2, 0.7);
  const double b = 0.05;
  Eigen::VectorXd controls(lattice.control_count());
  for (int c = 0; c < lattice.control_count(); ++c)
    controls[c] = a.dot(lattice.ControlPosition(c)) + b;
  const Eigen::VectorXd expected = (points * a).array() + b;
  EXPECT_LT((B * controls - expected).lpNorm<Eigen::Infinity>(), 1e-14);
}

TEST(SplineLattice, NumbersControlsByTheGeometryAlone) {
  // The same points in another order give the same controls, each point the same weights.
  std::mt19937 rng(6);
  const Eigen::MatrixXd points = RandomPoints(50, 0.05, &rng);
  Eigen::MatrixXd reversed = points.colwise().reverse();
  const Eigen::Vector3d origin = Eigen::Vector3d::Constant(-0.055);
  const SplineLattice forward(points, 0.01, origin), backward(reversed, 0.01, origin);
  ASSERT_EQ(forward.controls(), backward.controls());
  const Eigen::MatrixXd dense_forward = Eigen::MatrixXd(forward.basis());
  const Eigen::MatrixXd dense_backward = Eigen::MatrixXd(backward.basis());
  EXPECT_EQ(dense_forward, dense_backward.colwise().reverse());
}

// An 8 cm x 10 cm block, top spacing 1 cm, with a 2 cm arc at the front; its top is designed.
struct Block {
  TriMesh mesh;
  std::vector<bool> active;
};

Block MakeBlock() {
  const ProfileBlock shape = testing::SmallDesignBlock();
  Block block{MakeProfileBlock(shape), {}};
  for (Eigen::Index v = 0; v < block.mesh.vertices.rows(); ++v)
    block.active.push_back(OnProfileBlockTop(shape, block.mesh.vertices.row(v)));
  return block;
}

Eigen::VectorXd RandomVector(Eigen::Index size, double scale, std::mt19937* rng) {
  std::normal_distribution<double> normal(0, scale);
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i) v[i] = normal(*rng);
  return v;
}

TEST(SplineDesignSpace, PullBackIsTheExactTranspose) {
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kSpline,
                                  kSpacing);
  ASSERT_GT(p.size(), 0);
  std::mt19937 rng(11);
  const Eigen::VectorXd x = RandomVector(p.size(), 1e-3, &rng);
  const Eigen::VectorXd flat = RandomVector(3 * block.mesh.vertices.rows(), 1.0, &rng);
  const Vertices G = Eigen::Map<const Vertices>(flat.data(), block.mesh.vertices.rows(), 3);
  const auto phi = [&](const Eigen::VectorXd& c) { return G.cwiseProduct(p.Positions(c)).sum(); };
  const Eigen::VectorXd gradient = p.PullBack(G);
  std::string report;
  // φ is linear in the controls: central differences carry round-off only (~1e-12 relative
  // at the best step, as for the filter's test); 1e-8 fails any wrong entry.
  const double error = testing::WorstGradientError(
      phi, gradient, x, 1e-3 * gradient.lpNorm<Eigen::Infinity>(), testing::StepSweep(1e-2, 4),
      /*random_directions=*/8, /*max_coordinates=*/p.size(), /*seed=*/3, &report);
  EXPECT_LT(error, 1e-8) << report;
  std::cout << p.size() << " controls for " << p.active_vertices().size()
            << " designed vertices, worst finite-difference error " << error << "\n";
}

TEST(SplineDesignSpace, BoxKeepsEveryVertexWithinTheMoveAndMovesAreDisplacements) {
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kSpline,
                                  kSpacing);
  const double move = 2e-3;
  const double half = p.BoxHalfWidthForMove(move);
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> sign(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd corner(p.size());  // a corner of the box: the largest moves it allows
    for (Eigen::Index i = 0; i < corner.size(); ++i) corner[i] = sign(rng) ? half : -half;
    const Eigen::VectorXd moves = p.VertexMoves(corner);
    EXPECT_LE(moves.maxCoeff(), move * (1 + 1e-12));
    const Vertices moved = p.Positions(corner);
    for (Eigen::Index i = 0; i < moves.size(); ++i) {
      const int v = p.active_vertices()[i];
      EXPECT_NEAR((moved.row(v) - block.mesh.vertices.row(v)).norm(), moves[i], 1e-15);
    }
  }
  // The box is tight: all controls at +half move every vertex by exactly the cap.
  EXPECT_NEAR(p.VertexMoves(Eigen::VectorXd::Constant(p.size(), half)).minCoeff(), move, 1e-15);
}

TEST(SplineDesignSpace, DesignForProjectsOntoTheSpace) {
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kSpline,
                                  kSpacing);
  EXPECT_LT(p.DesignFor(block.mesh.vertices).lpNorm<Eigen::Infinity>(), 1e-15);
  std::mt19937 rng(13);
  const Eigen::VectorXd x = RandomVector(p.size(), 1e-3, &rng);
  const Vertices surface = p.Positions(x);
  // A surface in the space comes back (up to the minimum-norm choice among redundant
  // controls): measured 4e-9 m off on ~1 mm moves, the Tikhonov ε's damping of the controls
  // the designed vertices reach only through corner weights; bound 1e-5 of the move, and a
  // wrong fit (a transposed or unweighted B) is off by the move itself.
  const Vertices again = p.Positions(p.DesignFor(surface));
  EXPECT_LT((again - surface).cwiseAbs().maxCoeff(), 1e-5 * 1e-3);
  // One that is not (a single vertex raised) comes back as its least-squares fit: the fit
  // reduces the misfit and stays in the space.
  Vertices bump = block.mesh.vertices;
  const int v = p.active_vertices()[p.active_vertices().size() / 2];
  bump(v, 1) += 1e-3;
  const Vertices fitted = p.Positions(p.DesignFor(bump));
  EXPECT_LT((fitted - bump).norm(), (block.mesh.vertices - bump).norm());
  EXPECT_GT((fitted - block.mesh.vertices).norm(), 0.0);
}

TEST(SplineDesignSpace, SameControlsGiveTheSameSurfaceOnEveryMesh) {
  // The designed square |x|, |z| ≤ 0.1 m of flat grids at 10 and 5 mm spacing: the lattice
  // depends on the square, not on the mesh, so both have the same controls, and one control
  // vector moves every vertex the 10 mm grid shares with the 5 mm grid to the same height.
  constexpr double kHalfWidth = 0.12, kDesigned = 0.1;
  struct Level {
    TriMesh mesh;
    std::vector<bool> active;
  };
  auto make = [&](int cells) {
    Level level{testing::MakeFlatGrid(kHalfWidth, cells), {}};
    for (Eigen::Index v = 0; v < level.mesh.vertices.rows(); ++v)
      level.active.push_back(std::max(std::abs(level.mesh.vertices(v, 0)),
                                      std::abs(level.mesh.vertices(v, 2))) < kDesigned + 1e-9);
    return level;
  };
  const Level coarse = make(24), fine = make(48);
  const SupportParameterization pc(coarse.mesh, coarse.active, DesignParameterization::kSpline,
                                   0.03);
  const SupportParameterization pf(fine.mesh, fine.active, DesignParameterization::kSpline, 0.03);
  ASSERT_EQ(pc.size(), pf.size());
  std::mt19937 rng(14);
  const Eigen::VectorXd controls = RandomVector(pc.size(), 1e-3, &rng);
  const Vertices hc = pc.Positions(controls), hf = pf.Positions(controls);
  int shared = 0;
  double worst = 0;
  for (Eigen::Index c = 0; c < coarse.mesh.vertices.rows(); ++c) {
    for (Eigen::Index f = 0; f < fine.mesh.vertices.rows(); ++f) {
      if ((coarse.mesh.vertices.row(c) - fine.mesh.vertices.row(f)).norm() > 1e-12) continue;
      worst = std::max(worst, std::abs(hc(c, 1) - hf(f, 1)));
      ++shared;
    }
  }
  EXPECT_EQ(shared, coarse.mesh.vertices.rows());
  // Both evaluate the same spline at the same point: equal up to round-off (1e-3 m controls).
  EXPECT_LT(worst, 1e-17 + 1e-13 * 1e-3);
}

}  // namespace
}  // namespace ergo
