#include "ergo/mesh/tet_boundary.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

TEST(Mesh, BoundaryOfASingleTetIsItsFourOutwardFaces) {
  TetMesh tet;
  tet.vertices.resize(4, 3);
  tet.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tet.tets.resize(1, 4);
  tet.tets << 0, 1, 2, 3;
  const TetBoundary boundary = ExtractBoundary(tet);
  EXPECT_EQ(boundary.surface.triangles.rows(), 4);
  EXPECT_NEAR(EnclosedVolume(boundary.surface), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(boundary.component_count, 1);
}

TEST(Mesh, BoundaryOfATetGridIsTheClosedOutwardBoxSurface) {
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {1, 2, 3}, {2, 2, 2});
  const TetBoundary boundary = ExtractBoundary(grid);
  // 6 faces of 2x2 squares, 2 triangles each; 27 lattice points minus the centre.
  EXPECT_EQ(boundary.surface.triangles.rows(), 6 * 4 * 2);
  EXPECT_EQ(boundary.surface.vertices.rows(), 26);
  EXPECT_NEAR(EnclosedVolume(boundary.surface), 6.0, 1e-12);
  EXPECT_EQ(boundary.component_count, 1);
  // The centre vertex (1, 1, 1.5) is interior: not on the surface.
  for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v) {
    const bool centre = (grid.vertices.row(v) - Eigen::RowVector3d(0.5, 1, 1.5)).norm() < 1e-12;
    EXPECT_EQ(boundary.tet_to_surface[v] < 0, centre);
  }
  // The maps are inverse to each other and positions agree.
  for (Eigen::Index s = 0; s < boundary.surface.vertices.rows(); ++s) {
    EXPECT_EQ(boundary.tet_to_surface[boundary.surface_to_tet[s]], s);
    EXPECT_EQ(boundary.surface.vertices.row(s), grid.vertices.row(boundary.surface_to_tet[s]));
  }
  // Closed and consistently oriented: each directed edge once, its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      ++directed[{boundary.surface.triangles(f, k), boundary.surface.triangles(f, (k + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
}

TEST(Mesh, BoundaryOfAHollowGridHasTwoComponents) {
  // A 3x3x3 grid with its central cube's six tets removed: outer box + inner cavity.
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {3, 3, 3}, {3, 3, 3});
  TetMesh hollow;
  hollow.vertices = grid.vertices;
  std::vector<int> kept;
  for (Eigen::Index t = 0; t < grid.tets.rows(); ++t) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += grid.vertices.row(grid.tets(t, k)).transpose() / 4;
    if (!((centroid.array() > 1).all() && (centroid.array() < 2).all())) kept.push_back(int(t));
  }
  hollow.tets.resize(static_cast<Eigen::Index>(kept.size()), 4);
  for (size_t i = 0; i < kept.size(); ++i) hollow.tets.row(i) = grid.tets.row(kept[i]);
  const TetBoundary boundary = ExtractBoundary(hollow);
  EXPECT_EQ(boundary.component_count, 2);
  // Outer box volume 27 minus the cavity 1 (the cavity's faces point into the hole).
  EXPECT_NEAR(EnclosedVolume(boundary.surface), 26.0, 1e-12);
}

}  // namespace
}  // namespace ergo
