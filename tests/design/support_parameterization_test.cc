// SupportParameterization, all three kinds, on a small block whose top (flat part and rounded
// front edge) is designed: the pull-back is the exact transpose of Positions (finite
// differences component-wise, along random directions and along the gradient), vertex moves
// are the displacement lengths, DesignFor inverts Positions, and the filter keeps constants,
// acts as the identity off the designed triangles, tends to the identity as r → 0, and its
// copies run in parallel threads.
#include "ergo/design/support_parameterization.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/surface_geometry.h"
#include "problems/profile_block.h"
#include "tests/support/design_block.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

constexpr double kRadius = 0.025;  // m: 2.5 top edges

// An 8 cm x 10 cm block, top spacing 1 cm, with a 2 cm arc at the front. Its top is designed,
// and so is one bottom corner vertex (`lone`), which lies in no designed triangle.
struct Block {
  TriMesh mesh;
  std::vector<bool> active;
  int lone = -1;
};

Block MakeBlock() {
  const ProfileBlock shape = testing::SmallDesignBlock();
  Block block{MakeProfileBlock(shape), {}, -1};
  for (Eigen::Index v = 0; v < block.mesh.vertices.rows(); ++v) {
    const Eigen::Vector3d p = block.mesh.vertices.row(v);
    block.active.push_back(OnProfileBlockTop(shape, p));
    if (block.lone < 0 && p.y() < shape.bottom_y + 1e-9) block.lone = static_cast<int>(v);
  }
  block.active[block.lone] = true;
  return block;
}

const DesignParameterization kKinds[] = {DesignParameterization::kPositions,
                                         DesignParameterization::kNormalDisplacement,
                                         DesignParameterization::kFiltered};

std::string Name(DesignParameterization kind) {
  switch (kind) {
    case DesignParameterization::kPositions:
      return "positions";
    case DesignParameterization::kNormalDisplacement:
      return "normal";
    case DesignParameterization::kFiltered:
      return "filtered";
    case DesignParameterization::kSpline:
      return "spline";  // tests/design/spline_design_space_test.cc
  }
  return "?";
}

Eigen::VectorXd RandomVector(Eigen::Index size, double scale, std::mt19937* rng) {
  std::normal_distribution<double> normal(0, scale);
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i) v[i] = normal(*rng);
  return v;
}

// A design near the initial one: x₀ plus a random move of about 1 mm.
Eigen::VectorXd RandomDesign(const SupportParameterization& p, std::mt19937* rng) {
  return p.InitialDesign() + RandomVector(p.size(), 1e-3, rng);
}

Vertices RandomField(Eigen::Index rows, std::mt19937* rng) {
  const Eigen::VectorXd flat = RandomVector(3 * rows, 1.0, rng);
  return Eigen::Map<const Vertices>(flat.data(), rows, 3);
}

double Inner(const Vertices& a, const Vertices& b) { return a.cwiseProduct(b).sum(); }

TEST(Design, FilteredPullBackIsTheExactTranspose) {
  const Block block = MakeBlock();
  struct Space {
    DesignParameterization kind;
    bool l2_metric;
  };
  for (const Space space : {Space{kKinds[0], false}, Space{kKinds[1], false},
                            Space{kKinds[2], false}, Space{kKinds[2], true}}) {
    const std::string name = Name(space.kind) + (space.l2_metric ? " (L² metric)" : "");
    const SupportParameterization p(block.mesh, block.active, space.kind, kRadius, space.l2_metric);
    std::mt19937 rng(11);
    const Eigen::VectorXd theta = RandomDesign(p, &rng);
    const Vertices G = RandomField(block.mesh.vertices.rows(), &rng);
    const auto phi = [&](const Eigen::VectorXd& x) { return Inner(G, p.Positions(x)); };
    const Eigen::VectorXd gradient = p.PullBack(G);
    std::string report;
    // φ is linear in θ, so central differences have no truncation error: what is left is
    // round-off, eps·|φ|/h ≈ 1e-16 · 10 / 1e-2 against gradient components of ~0.1–1, i.e.
    // ~1e-12 relative at the best step. 1e-8 leaves four decades and still fails any wrong
    // entry (the forward-matrix mistake below is off by > 1e-2). Floor: 1e-3 of the largest
    // component, for components that nearly vanish.
    const double floor = 1e-3 * gradient.lpNorm<Eigen::Infinity>();
    const double error = testing::WorstGradientError(
        phi, gradient, theta, floor, testing::StepSweep(1e-2, 4), /*random_directions=*/8,
        /*max_coordinates=*/p.size(), /*seed=*/3, &report);
    EXPECT_LT(error, 1e-8) << name << ": " << report;
    std::cout << name << ": " << p.size() << " variables, worst finite-difference error " << error
              << "\n";
  }
}

TEST(Design, L2MetricBoxKeepsEveryVertexWithinTheMove) {
  // The box |θ̃ᵢ| ≤ BoxHalfWidthForMove(m) at its corners (every variable at ±the half-width,
  // random signs) moves no vertex farther than m; without the metric the half-width is m.
  const Block block = MakeBlock();
  const SupportParameterization l2(block.mesh, block.active, DesignParameterization::kFiltered,
                                   kRadius, true);
  const SupportParameterization raw(block.mesh, block.active, DesignParameterization::kFiltered,
                                    kRadius, false);
  constexpr double kMove = 2e-3;
  EXPECT_EQ(raw.BoxHalfWidthForMove(kMove), kMove);
  const double half_width = l2.BoxHalfWidthForMove(kMove);
  EXPECT_GT(half_width, 0);
  EXPECT_NE(half_width, kMove);
  std::mt19937 rng(21);
  std::bernoulli_distribution sign;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd corner(l2.size());
    for (Eigen::Index i = 0; i < corner.size(); ++i)
      corner[i] = sign(rng) ? half_width : -half_width;
    EXPECT_LE(l2.VertexMoves(corner).maxCoeff(), kMove * (1 + 1e-12));
  }
}

TEST(Design, FilteredPullBackByTheForwardMatrixFailsTheCheck) {
  // The mistake PolyFEM's LinearFilter once made: F (Nᵀg) instead of Fᵀ (Nᵀg). F ≠ Fᵀ here
  // because the vertex areas differ (half areas on the rim), and the check above sees it.
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kFiltered,
                                  kRadius);
  const Vertices normals = VertexNormals(block.mesh);
  std::mt19937 rng(12);
  const Vertices G = RandomField(block.mesh.vertices.rows(), &rng);
  Eigen::VectorXd normal_part(p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i)
    normal_part[i] = G.row(p.active_vertices()[i]).dot(normals.row(p.active_vertices()[i]));
  const Vertices moved = p.Positions(normal_part) - block.mesh.vertices;
  Eigen::VectorXd forward(p.size());  // F (Nᵀ G), read off the normal displacement
  for (Eigen::Index i = 0; i < p.size(); ++i)
    forward[i] = moved.row(p.active_vertices()[i]).dot(normals.row(p.active_vertices()[i]));
  const auto phi = [&](const Eigen::VectorXd& x) { return Inner(G, p.Positions(x)); };
  std::string report;
  const double error = testing::WorstGradientError(
      phi, forward, p.InitialDesign(), 1e-3 * forward.lpNorm<Eigen::Infinity>(),
      testing::StepSweep(1e-2, 4), 8, p.size(), 3, &report);
  EXPECT_GT(error, 1e-2) << report;
  std::cout << "forward matrix as the pull-back: worst error " << error << "\n";
}

TEST(Design, FilteredVertexMovesAreTheDisplacementLengths) {
  const Block block = MakeBlock();
  for (DesignParameterization kind : kKinds) {
    const SupportParameterization p(block.mesh, block.active, kind, kRadius);
    std::mt19937 rng(13);
    const Eigen::VectorXd theta = RandomDesign(p, &rng);
    const Eigen::VectorXd step = RandomVector(p.size(), 1e-3, &rng);
    const Vertices moved = p.Positions(theta + step) - p.Positions(theta);
    const Eigen::VectorXd moves = p.VertexMoves(step);
    ASSERT_EQ(moves.size(), p.active_vertices().size());
    // Positions is affine, so the two agree up to the round-off of differencing coordinates
    // of ~0.05 m (≈ 1e-17 m) and of the solve (≈ 1e-16 of the move): 1e-12 of the largest
    // move is far above both and far below any wrong length.
    for (Eigen::Index i = 0; i < moves.size(); ++i)
      EXPECT_NEAR(moves[i], moved.row(p.active_vertices()[i]).norm(), 1e-12 * moves.maxCoeff())
          << Name(kind) << " vertex " << p.active_vertices()[i];
  }
}

TEST(Design, FilterPreservesConstants) {
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kFiltered,
                                  kRadius);
  const Vertices normals = VertexNormals(block.mesh);
  const double lift = 0.003;  // m
  const Vertices lifted = p.Positions(Eigen::VectorXd::Constant(p.size(), lift));
  const Vertices expected = block.mesh.vertices + lift * normals;
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    const int v = p.active_vertices()[i];
    // F·1 = 1 because K·1 = 0; round-off of the solve only (κ(A) ~ 10 here).
    EXPECT_LT((lifted.row(v) - expected.row(v)).norm(), 1e-14) << "vertex " << v;
  }
  // A non-constant θ is changed by the filter (else the check above proves nothing).
  std::mt19937 rng(14);
  const Eigen::VectorXd theta = RandomVector(p.size(), 1e-3, &rng);
  const Vertices bumpy = p.Positions(theta);
  EXPECT_GT((bumpy - block.mesh.vertices).norm(), 0);
  EXPECT_LT((bumpy - block.mesh.vertices).norm(), 0.5 * theta.norm());
}

TEST(Design, FilterActsAsTheIdentityOffTheDesignedTriangles) {
  // The lone bottom vertex is active but in no designed triangle: θ moves it alone, by θ
  // along its normal, and it does not feel the other θ.
  const Block block = MakeBlock();
  const SupportParameterization p(block.mesh, block.active, DesignParameterization::kFiltered,
                                  kRadius);
  Eigen::Index lone = -1;
  for (Eigen::Index i = 0; i < p.size(); ++i)
    if (p.active_vertices()[i] == block.lone) lone = i;
  ASSERT_GE(lone, 0);
  const Vertices normals = VertexNormals(block.mesh);
  const Eigen::VectorXd only_lone = 0.002 * Eigen::VectorXd::Unit(p.size(), lone);
  const Vertices moved = p.Positions(only_lone) - block.mesh.vertices;
  EXPECT_LT((moved.row(block.lone) - 0.002 * normals.row(block.lone)).norm(), 1e-16);
  EXPECT_EQ(moved.norm(), moved.row(block.lone).norm());  // nothing else moved
  Eigen::VectorXd all_but_lone = Eigen::VectorXd::Constant(p.size(), 0.002);
  all_but_lone[lone] = 0;
  EXPECT_EQ((p.Positions(all_but_lone) - block.mesh.vertices).row(block.lone).norm(), 0.0);
}

TEST(Design, FilterTendsToTheIdentityAsTheRadiusShrinks) {
  // F = I − R²M⁻¹K + O(R⁴): with r = 1 µm, R²/h² ≈ 1e-9, so the filtered and the raw
  // normal displacement agree to ~1e-9 relative (1e-7 allowed); with r = 2.5 cm they do not.
  const Block block = MakeBlock();
  const SupportParameterization raw(block.mesh, block.active,
                                    DesignParameterization::kNormalDisplacement);
  std::mt19937 rng(15);
  const Eigen::VectorXd theta = RandomVector(raw.size(), 1e-3, &rng);
  const Vertices unfiltered = raw.Positions(theta) - block.mesh.vertices;
  for (double r : {1e-6, kRadius}) {
    const SupportParameterization p(block.mesh, block.active, DesignParameterization::kFiltered, r);
    const double difference =
        (p.Positions(theta) - block.mesh.vertices - unfiltered).norm() / unfiltered.norm();
    std::cout << "r = " << r << " m: relative difference to the raw field " << difference << "\n";
    if (r < 1e-3) {
      EXPECT_LT(difference, 1e-7);
    } else {
      EXPECT_GT(difference, 0.3);
    }
  }
}

TEST(Design, DesignForInvertsPositionsForEveryKind) {
  const Block block = MakeBlock();
  for (int k = 0; k < 4; ++k) {
    const DesignParameterization kind = kKinds[std::min(k, 2)];  // 3: filtered, L² metric
    const SupportParameterization p(block.mesh, block.active, kind, kRadius, k == 3);
    std::mt19937 rng(16);
    const Eigen::VectorXd x = RandomDesign(p, &rng);
    const Eigen::VectorXd back = p.DesignFor(p.Positions(x));
    ASSERT_EQ(back.size(), x.size());
    if (kind == DesignParameterization::kPositions) {
      EXPECT_EQ(back, x);
    } else {
      // θ → N F θ → Nᵀ, then M⁻¹A: round-off amplified by κ(M⁻¹A) = 1 + R²λmax(M⁻¹K),
      // about 20 here; 1e-12 of |θ| (~1e-3 m) is a hundred times that.
      EXPECT_LT((back - x).lpNorm<Eigen::Infinity>(), 1e-12 * x.lpNorm<Eigen::Infinity>())
          << Name(kind);
    }
    EXPECT_EQ(p.DesignFor(block.mesh.vertices), p.InitialDesign()) << Name(kind);
  }
}

TEST(Design, DesignForKeepsTheNormalPartOfAMove) {
  // Tangential moves are not in the normal kinds' design space: DesignFor drops them.
  const Block block = MakeBlock();
  const Vertices normals = VertexNormals(block.mesh);
  std::mt19937 rng(17);
  Vertices tangential = 1e-3 * RandomField(block.mesh.vertices.rows(), &rng);
  for (Eigen::Index v = 0; v < tangential.rows(); ++v)
    tangential.row(v) -= tangential.row(v).dot(normals.row(v)) * normals.row(v);
  for (DesignParameterization kind :
       {DesignParameterization::kNormalDisplacement, DesignParameterization::kFiltered}) {
    const SupportParameterization p(block.mesh, block.active, kind, kRadius);
    const Eigen::VectorXd x = RandomDesign(p, &rng);
    const Eigen::VectorXd back = p.DesignFor(p.Positions(x) + tangential);
    EXPECT_LT((back - x).lpNorm<Eigen::Infinity>(), 1e-12 * x.lpNorm<Eigen::Infinity>())
        << Name(kind);
  }
}

TEST(Design, FilteredCopiesAgreeAndRunInParallelThreads) {
  const Block block = MakeBlock();
  auto original = std::make_unique<SupportParameterization>(
      block.mesh, block.active, DesignParameterization::kFiltered, kRadius);
  constexpr int kInputs = 8, kRounds = 200;
  std::mt19937 rng(18);
  std::vector<Eigen::VectorXd> designs;
  std::vector<Vertices> fields;
  std::vector<Vertices> expected_positions;
  std::vector<Eigen::VectorXd> expected_gradients, expected_moves, expected_designs;
  for (int k = 0; k < kInputs; ++k) {
    designs.push_back(RandomDesign(*original, &rng));
    fields.push_back(RandomField(block.mesh.vertices.rows(), &rng));
    expected_positions.push_back(original->Positions(designs[k]));
    expected_gradients.push_back(original->PullBack(fields[k]));
    expected_moves.push_back(original->VertexMoves(designs[k]));
    expected_designs.push_back(original->DesignFor(fields[k]));
  }
  // The copies must own their factors: the original is gone before they are used.
  SupportParameterization first(*original);
  SupportParameterization second = first;
  original.reset();
  EXPECT_EQ(first.filter_radius(), kRadius);
  EXPECT_EQ(second.size(), static_cast<int>(expected_moves[0].size()));

  // Same factor, same arithmetic: the results agree to round-off (1e-14 relative allows BLAS
  // to split a sum differently when several threads call it).
  auto worst_mismatch = [&](const SupportParameterization& p) {
    double worst = 0;
    for (int round = 0; round < kRounds; ++round) {
      const int k = round % kInputs;
      worst = std::max(worst, (p.Positions(designs[k]) - expected_positions[k]).norm() /
                                  expected_positions[k].norm());
      worst = std::max(worst, (p.PullBack(fields[k]) - expected_gradients[k]).norm() /
                                  expected_gradients[k].norm());
      worst = std::max(
          worst, (p.VertexMoves(designs[k]) - expected_moves[k]).norm() / expected_moves[k].norm());
      worst = std::max(worst, (p.DesignFor(fields[k]) - expected_designs[k]).norm() /
                                  expected_designs[k].norm());
    }
    return worst;
  };
  double worst_first = -1, worst_second = -1;
  std::thread a([&] { worst_first = worst_mismatch(first); });
  std::thread b([&] { worst_second = worst_mismatch(second); });
  a.join();
  b.join();
  std::cout << "copies in two threads: worst relative mismatch " << worst_first << ", "
            << worst_second << "\n";
  EXPECT_LT(worst_first, 1e-14);
  EXPECT_LT(worst_second, 1e-14);
  EXPECT_GE(worst_first, 0);  // the threads ran
  EXPECT_GE(worst_second, 0);
}

TEST(Design, FilterRadiusMustBePositive) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // BLAS may have started threads
  const Block block = MakeBlock();
  for (double r : {0.0, -0.01, std::nan("")}) {
    EXPECT_DEATH(
        SupportParameterization(block.mesh, block.active, DesignParameterization::kFiltered, r),
        "filter radius")
        << r;
  }
  // The other kinds have no filter and ignore the radius.
  EXPECT_EQ(SupportParameterization(block.mesh, block.active,
                                    DesignParameterization::kNormalDisplacement, 0.0)
                .filter_radius(),
            0.0);
}

}  // namespace
}  // namespace ergo
