// The self-intersection test: each way two triangles can meet (crossing, a fold along a
// shared edge, an overlap at a shared corner) against the ways they may touch, and its work
// budget on the crafted meshes of issue 19, at small sizes: a stack of parallel triangles and
// a closed sliver double cone, where every pair of boxes overlaps. With the default budget
// both are tested completely and found clean; with a smaller one the test stops and says so,
// and the mesh check calls that a problem, never "clean". Copies of one triangle or tet are
// counted one by one.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/self_intersection.h"
#include "tests/support/crafted_meshes.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// Two triangles sharing the edge (0, 1) of the unit square's diagonal, consistently
// oriented; the second's free corner is `s`.
TriMesh EdgePair(const Eigen::Vector3d& s) {
  TriMesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, s.x(), s.y(), s.z();
  mesh.triangles.resize(2, 3);
  mesh.triangles << 0, 1, 2, 1, 0, 3;
  return mesh;
}

TEST(Mesh, SelfIntersectionAlongASharedEdgeIsOnlyAFold) {
  // The free corners on opposite sides of the edge: a flat pair, no intersection.
  EXPECT_TRUE(FindSelfIntersections(EdgePair({0.5, -1, 0})).pairs.empty());
  // Bent out of the plane: they meet only along the edge.
  EXPECT_TRUE(FindSelfIntersections(EdgePair({0.3, 0.5, 0.5})).pairs.empty());
  // Folded onto each other in the plane: they overlap.
  const SelfIntersections fold = FindSelfIntersections(EdgePair({0.3, 0.5, 0}));
  ASSERT_TRUE(fold.checked);
  ASSERT_EQ(fold.pairs.size(), 1u);
  EXPECT_EQ(fold.pairs[0], std::make_pair(0, 1));
}

// A fan of three triangles around vertex 0 (the first in the plane z = 0, corners 1 and 2
// on the axes); the first and the last share only vertex 0.
TriMesh Fan(const Eigen::Vector3d& third, const Eigen::Vector3d& last) {
  TriMesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, third.x(), third.y(), third.z(), last.x(), last.y(),
      last.z();
  mesh.triangles.resize(3, 3);
  mesh.triangles << 0, 1, 2, 0, 2, 3, 0, 3, 4;
  return mesh;
}

TEST(Mesh, SelfIntersectionAtASharedCornerNeedsMoreThanTheCorner) {
  const Eigen::Vector3d minus_x(-1, 0, 0);
  // The last triangle turns down below the x axis: it meets the first only at vertex 0.
  EXPECT_TRUE(FindSelfIntersections(Fan(minus_x, {0, -1, 0})).pairs.empty());
  // Bent up out of the plane, over the first triangle: still only vertex 0 in common.
  EXPECT_TRUE(FindSelfIntersections(Fan(minus_x, {0.5, 0.5, 1})).pairs.empty());
  // Swung over the first triangle in the plane: their wedges overlap near vertex 0 (and the
  // last folds onto the middle one along their shared edge).
  const SelfIntersections overlap = FindSelfIntersections(Fan(minus_x, {0.5, 0.5, 0}));
  const std::vector<std::pair<int, int>> folded = {{0, 2}, {1, 2}};
  EXPECT_EQ(overlap.pairs, folded);
  // Piercing it: the last triangle's far edge passes through the first at (0.3, 0.3, 0).
  const SelfIntersections pierce = FindSelfIntersections(Fan({0.3, 0.3, 0.5}, {0.3, 0.3, -0.5}));
  ASSERT_EQ(pierce.pairs.size(), 1u);
  EXPECT_EQ(pierce.pairs[0], std::make_pair(0, 2));
}

SelfIntersectionOptions SmallBudget() {
  SelfIntersectionOptions options;
  options.min_pair_tests = 10000;
  options.max_pair_tests_per_triangle = 1;
  options.max_seconds = 0;  // no time limit: the outcome is deterministic
  return options;
}

TEST(Mesh, SelfIntersectionTestStopsAtItsPairBudgetAndEstimatesTheRest) {
  constexpr int kTriangles = 2000;  // 1,999,000 pairs, every one a candidate
  const TriMesh stack = testing::ParallelTriangleStack(kTriangles);
  const SelfIntersections complete = FindSelfIntersections(stack);
  EXPECT_TRUE(complete.checked);
  EXPECT_FALSE(complete.out_of_budget);
  EXPECT_TRUE(complete.pairs.empty());
  EXPECT_EQ(complete.pair_tests, kTriangles * (kTriangles - 1) / 2);

  const SelfIntersections stopped = FindSelfIntersections(stack, SmallBudget());
  EXPECT_TRUE(stopped.checked);
  EXPECT_TRUE(stopped.out_of_budget);
  EXPECT_FALSE(stopped.stopped_by_time);
  EXPECT_EQ(stopped.pair_test_limit, 10000);
  EXPECT_EQ(stopped.pair_tests, 10000);
  // Every sampled box overlaps all others: the estimate is exact here.
  EXPECT_DOUBLE_EQ(stopped.estimated_candidates, kTriangles * (kTriangles - 1) / 2.0);
  const std::string text = stopped.BudgetReport();
  EXPECT_NE(text.find("self-intersection test stopped after "), std::string::npos) << text;
  EXPECT_NE(text.find(" and 10,000 triangle-pair tests (its limit for a mesh of this size)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("about 2e+06 pairs of triangles whose bounding boxes overlap, 1999 per "
                      "triangle"),
            std::string::npos)
      << text;
  EXPECT_EQ(complete.BudgetReport(), "");

  // The budget per triangle wins over the minimum for a large enough mesh.
  SelfIntersectionOptions per_triangle = SmallBudget();
  per_triangle.max_pair_tests_per_triangle = 50;
  EXPECT_EQ(FindSelfIntersections(stack, per_triangle).pair_tests, 50 * kTriangles);
}

TEST(Mesh, SelfIntersectionTestStopsAtItsTimeLimit) {
  SelfIntersectionOptions options;
  options.max_seconds = 1e-9;  // over before the first pair
  const SelfIntersections stopped =
      FindSelfIntersections(testing::ParallelTriangleStack(100), options);
  EXPECT_TRUE(stopped.out_of_budget);
  EXPECT_TRUE(stopped.stopped_by_time);
  EXPECT_EQ(stopped.pair_tests, 0);
  EXPECT_NE(stopped.BudgetReport().find("triangle-pair tests (its time limit)"), std::string::npos)
      << stopped.BudgetReport();
}

TEST(Mesh, CheckCallsAnUnfinishedSelfIntersectionTestAProblem) {
  const TriMesh cone = testing::SliverDoubleCone(500);  // 1000 slivers, 499,500 pairs
  MeshCheckOptions options;
  options.require_closed = true;
  const MeshCheckReport clean = CheckTriMesh(cone, "cone", options);
  EXPECT_EQ(clean.ExitCode(), 0) << clean.FullReport();

  options.self_intersection = SmallBudget();
  const MeshCheckReport report = CheckTriMesh(cone, "cone", options);
  EXPECT_EQ(report.ExitCode(), 1) << report.FullReport();
  ASSERT_EQ(report.issues.size(), 1u) << report.FullReport();
  const MeshIssue& issue = report.issues[0];
  EXPECT_EQ(issue.code, "self-intersection-test-incomplete");
  EXPECT_EQ(issue.severity, Severity::kProblem);
  EXPECT_NE(issue.what.find("none of the tested pairs intersect, the rest are unknown"),
            std::string::npos)
      << issue.what;
  EXPECT_NE(issue.fix.find("re-mesh with well-shaped triangles"), std::string::npos);
  EXPECT_NE(report.BriefReport().find("self-intersection-test-incomplete"), std::string::npos);
}

// `pages` triangles around the z axis like the pages of an open book, each through the
// spine from (0, 0, -1) to (0, 0, 1): every pair intersects, and no two share a vertex.
TriMesh Book(int pages) {
  TriMesh mesh;
  mesh.vertices.resize(3 * pages, 3);
  mesh.triangles.resize(pages, 3);
  for (int i = 0; i < pages; ++i) {
    const double angle = std::acos(-1.0) * i / pages;
    const double x = 0.1 * std::cos(angle), y = 0.1 * std::sin(angle);
    mesh.vertices.row(3 * i) << x, y, -1;
    mesh.vertices.row(3 * i + 1) << -x, -y, -1;
    mesh.vertices.row(3 * i + 2) << 0, 0, 1 + 1e-3 * i;
    mesh.triangles.row(i) << 3 * i, 3 * i + 1, 3 * i + 2;
  }
  return mesh;
}

TEST(Mesh, CheckListsIntersectionsFoundBeforeTheBudgetRanOutAsAtLeast) {
  MeshCheckOptions options;
  options.self_intersection = SmallBudget();
  options.self_intersection.min_pair_tests = 5000;  // of 19,900, each an intersection
  options.self_intersection.max_pairs = 100000;
  const MeshCheckReport report = CheckTriMesh(Book(200), "book", options);
  const MeshIssue* crossings = report.Find("self-intersections");
  ASSERT_NE(crossings, nullptr) << report.FullReport();
  EXPECT_EQ(crossings->count, 5000);
  EXPECT_EQ(crossings->what.rfind("at least 5000 pairs of triangles intersect", 0), 0u)
      << crossings->what;
  const MeshIssue* incomplete = report.Find("self-intersection-test-incomplete");
  ASSERT_NE(incomplete, nullptr) << report.FullReport();
  EXPECT_NE(incomplete->what.find("the intersections listed are some of them"), std::string::npos)
      << incomplete->what;
}

TEST(Mesh, CheckCountsEveryCopyOfARepeatedTriangleAndTet) {
  const std::string dir = testing::MakeScratchDir("copies");
  testing::WriteDuplicateTrianglesObj(dir + "/copies.obj", 3000);
  const MeshCheckReport faces = CheckMeshFile(dir + "/copies.obj");
  ASSERT_NE(faces.Find("duplicate-faces"), nullptr) << faces.FullReport();
  EXPECT_EQ(faces.Find("duplicate-faces")->count, 2999);
  // Each copy is named against the first, with the lines of both.
  EXPECT_NE(faces.FullReport().find("triangle 1 (line 5) repeats triangle 0 (line 4)"),
            std::string::npos)
      << faces.FullReport();
  EXPECT_NE(faces.FullReport().find("triangle 5 (line 9) repeats triangle 0 (line 4)"),
            std::string::npos)
      << faces.FullReport();

  testing::WriteDuplicateTetsTetGen(dir + "/copies", 3000);
  const MeshCheckReport tets = CheckMeshFile(dir + "/copies.ele");
  ASSERT_NE(tets.Find("duplicate-tets"), nullptr) << tets.FullReport();
  EXPECT_EQ(tets.Find("duplicate-tets")->count, 2999);
  EXPECT_NE(tets.FullReport().find("tetrahedron 1 (line 3) repeats tetrahedron 0 (line 2)"),
            std::string::npos)
      << tets.FullReport();
  // The copies take no part in the face check (else each face would be shared 3000 times).
  EXPECT_EQ(tets.Find("non-manifold-tet-faces"), nullptr) << tets.FullReport();
}

}  // namespace
}  // namespace ergo
