#include "ergo/mesh/split_non_manifold_vertices.h"

#include <gtest/gtest.h>

#include "ergo/mesh/primitives.h"

namespace ergo {
namespace {

// Two closed tetrahedra sharing one corner (a pinch): the shared vertex gets one copy for the
// second fan; positions and triangle order are unchanged, and a manifold surface is returned
// as it was.
TEST(Mesh, PinchedVertexIsSplitIntoOneCopyPerFan) {
  TriMesh two;
  two.vertices.resize(7, 3);
  two.vertices << 0, 0, 0,           // shared corner
      1, 0, 0, 0, 1, 0, 0, 0, 1,     // first tet
      -1, 0, 0, 0, -1, 0, 0, 0, -1;  // second tet
  two.triangles.resize(8, 3);
  two.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,  // first
      0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5;               // second
  int split = -1;
  const TriMesh result = SplitNonManifoldVertices(two, &split);
  EXPECT_EQ(split, 1);
  ASSERT_EQ(result.vertices.rows(), 8);
  EXPECT_TRUE(result.vertices.row(7).isApprox(two.vertices.row(0)));
  for (int f = 0; f < 4; ++f) EXPECT_EQ(result.triangles.row(f), two.triangles.row(f));
  for (int f = 4; f < 8; ++f) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NE(result.triangles(f, k), 0);
      if (two.triangles(f, k) != 0) {
        EXPECT_EQ(result.triangles(f, k), two.triangles(f, k));
      }
    }
  }
  const TriMesh sphere = MakeIcosphere(1.0, 2);
  const TriMesh same = SplitNonManifoldVertices(sphere, &split);
  EXPECT_EQ(split, 0);
  EXPECT_EQ(same.triangles, sphere.triangles);
}

}  // namespace
}  // namespace ergo
