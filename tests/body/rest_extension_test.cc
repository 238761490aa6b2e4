// The soft support's interior following its designed top (ergo/body/rest_extension.h): a
// translation of the whole boundary moves every interior vertex by it (harmonic functions
// keep constants), the extension is bounded by its boundary values (maximum principle), and
// PullBack is Extend's exact transpose.
#include "ergo/body/rest_extension.h"

#include <random>

#include <gtest/gtest.h>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

struct Block {
  TetMesh mesh;
  std::vector<bool> top, bottom, side;
};

Block MakeBlock() {
  Block b;
  b.mesh = MakeTetGrid({0, 0, 0}, {0.1, 0.04, 0.1}, {5, 4, 5});
  const TetBoundary boundary = ExtractBoundary(b.mesh);
  const Eigen::Index n = b.mesh.vertices.rows();
  b.top.assign(n, false);
  b.bottom.assign(n, false);
  b.side.assign(n, false);
  for (Eigen::Index i = 0; i < boundary.surface_to_tet.size(); ++i) {
    const int v = boundary.surface_to_tet[i];
    const double y = b.mesh.vertices(v, 1);
    (y > 0.04 - 1e-9 ? b.top : y < 1e-9 ? b.bottom : b.side)[v] = true;
  }
  return b;
}

TEST(RestExtension, ATranslationOfTheWholeBoundaryMovesTheInteriorAlike) {
  const Block b = MakeBlock();
  std::vector<bool> designed(b.top.size()), fixed(b.top.size(), false);
  for (size_t v = 0; v < designed.size(); ++v) designed[v] = b.top[v] || b.bottom[v] || b.side[v];
  const RestExtension extension(b.mesh, designed, fixed);
  ASSERT_GT(extension.interior_count(), 10);
  Vertices shift = Vertices::Zero(b.mesh.vertices.rows(), 3);
  for (size_t v = 0; v < designed.size(); ++v)
    if (designed[v]) shift.row(v) << 1e-3, -2e-3, 5e-4;
  const Vertices moved = extension.Extend(shift);
  for (Eigen::Index v = 0; v < moved.rows(); ++v)
    EXPECT_LT((moved.row(v) - Eigen::RowVector3d(1e-3, -2e-3, 5e-4)).norm(), 1e-15) << v;
}

TEST(RestExtension, TheTopsMoveFadesTowardsTheHeldBaseAndPullBackIsItsTranspose) {
  const Block b = MakeBlock();
  std::vector<bool> fixed(b.top.size());
  for (size_t v = 0; v < fixed.size(); ++v) fixed[v] = b.bottom[v] || b.side[v];
  const RestExtension extension(b.mesh, b.top, fixed);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vertices designed = Vertices::Zero(b.mesh.vertices.rows(), 3);
  for (size_t v = 0; v < b.top.size(); ++v)
    if (b.top[v]) designed.row(v) << 0, 1e-3 * (1 + uniform(rng)), 0;  // up by 0–2 mm
  const Vertices moved = extension.Extend(designed);
  // Maximum principle: inside, between the fixed 0 and the top's largest lift; decreasing on
  // average towards the base.
  std::vector<double> layer_sum(5, 0.0);
  std::vector<int> layer_count(5, 0);
  for (Eigen::Index v = 0; v < moved.rows(); ++v) {
    EXPECT_GE(moved(v, 1), -1e-15);
    EXPECT_LE(moved(v, 1), 2e-3 + 1e-15);
    const int layer = static_cast<int>(std::lround(b.mesh.vertices(v, 1) / 0.01));
    layer_sum[layer] += moved(v, 1);
    ++layer_count[layer];
  }
  for (int layer = 1; layer < 5; ++layer)
    EXPECT_GT(layer_sum[layer] / layer_count[layer], layer_sum[layer - 1] / layer_count[layer - 1]);
  // ⟨PullBack(g), u_D⟩ = ⟨g, Extend(u_D)⟩ for any g and designed u_D.
  Vertices g(b.mesh.vertices.rows(), 3);
  for (Eigen::Index i = 0; i < g.size(); ++i) g.data()[i] = uniform(rng);
  const double left = (extension.PullBack(g).array() * designed.array()).sum();
  const double right = (g.array() * moved.array()).sum();
  EXPECT_NEAR(left, right, 1e-12 * std::abs(right));
  // Non-designed rows of the pull-back are zero.
  const Vertices back = extension.PullBack(g);
  for (size_t v = 0; v < b.top.size(); ++v)
    if (!b.top[v]) EXPECT_EQ(back.row(v).norm(), 0.0) << v;
}

}  // namespace
}  // namespace ergo
