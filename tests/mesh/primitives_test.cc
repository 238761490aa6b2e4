#include "ergo/mesh/primitives.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// Every directed edge appears once and its reverse once: closed and consistently oriented.
bool ClosedAndOriented(const TriMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f)
    for (int e = 0; e < 3; ++e) ++directed[{mesh.triangles(f, e), mesh.triangles(f, (e + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(Mesh, IcosphereIsClosedOutwardAndHasExpectedCounts) {
  const TriMesh sphere = MakeIcosphere(2.0, 3);
  EXPECT_EQ(sphere.vertices.rows(), 10 * 64 + 2);
  EXPECT_EQ(sphere.triangles.rows(), 20 * 64);
  EXPECT_TRUE(ClosedAndOriented(sphere));
  // Inscribed polyhedron: volume slightly below 4/3 pi r^3 (within 2 % at 1280 faces).
  const double exact = 4.0 / 3.0 * M_PI * 8.0;
  EXPECT_LT(EnclosedVolume(sphere), exact);
  EXPECT_GT(EnclosedVolume(sphere), 0.98 * exact);
}

TEST(Mesh, BoxIsClosedOutwardWithExactVolume) {
  const TriMesh box = MakeBox({0, 0, 0}, {0.5, 0.2, 0.4}, {5, 2, 4});
  EXPECT_TRUE(ClosedAndOriented(box));
  EXPECT_NEAR(EnclosedVolume(box), 0.5 * 0.2 * 0.4, 1e-15);
  // Lattice points on the surface: all minus interior (4*1*3).
  EXPECT_EQ(box.vertices.rows(), 6 * 3 * 5 - 4 * 1 * 3);
}

TEST(Mesh, TorusIsClosedOutward) {
  const TriMesh torus = MakeTorus(1.0, 0.25, 48, 24);
  EXPECT_TRUE(ClosedAndOriented(torus));
  const double exact = 2 * M_PI * M_PI * 1.0 * 0.25 * 0.25;
  EXPECT_NEAR(EnclosedVolume(torus), exact, 0.02 * exact);
}

TEST(Mesh, TetGridTetsArePositiveAndFillTheBox) {
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {1, 2, 3}, {2, 3, 4});
  EXPECT_EQ(grid.tets.rows(), 6 * 24);
  double total = 0;
  for (Eigen::Index t = 0; t < grid.tets.rows(); ++t) {
    const Eigen::Vector3d p0 = grid.vertices.row(grid.tets(t, 0));
    const double v =
        (Eigen::Vector3d(grid.vertices.row(grid.tets(t, 1))) - p0)
            .dot((Eigen::Vector3d(grid.vertices.row(grid.tets(t, 2))) - p0)
                     .cross(Eigen::Vector3d(grid.vertices.row(grid.tets(t, 3))) - p0)) /
        6.0;
    EXPECT_GT(v, 0);
    total += v;
  }
  EXPECT_NEAR(total, 6.0, 1e-12);
}

}  // namespace
}  // namespace ergo

namespace ergo {
namespace {

TEST(Mesh, HeightfieldBlockRaisesTheTopAndStaysClosed) {
  const auto bump = [](double x, double z) { return 0.01 * std::exp(-(x * x + z * z) / 0.01); };
  const TriMesh block = MakeHeightfieldBlock({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {8, 2, 8}, bump);
  EXPECT_TRUE(ClosedAndOriented(block));
  double top = -1;
  for (Eigen::Index v = 0; v < block.vertices.rows(); ++v)
    top = std::max(top, block.vertices(v, 1));
  EXPECT_NEAR(top, 0.01, 1e-15);  // the grid has a vertex at the bump's centre
  // Volume grows by the integral of the bump over the top (sampled): positive and small.
  const double added = EnclosedVolume(block) - 0.4 * 0.1 * 0.4;
  EXPECT_GT(added, 0);
  EXPECT_LT(added, 0.01 * M_PI * 0.01);  // below the exact Gaussian integral π w² h
}

}  // namespace
}  // namespace ergo
