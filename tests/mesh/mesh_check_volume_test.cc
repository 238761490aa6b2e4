// The tetrahedron checks: a structured grid passes; inverted, flat, repeated and overlapping
// tets are found and named; a file written with the opposite orientation convention gets
// one message saying so.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/tetgen_format.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

TetMesh Grid() { return MakeTetGrid({0, 0, 0}, {0.2, 0.1, 0.1}, {4, 2, 2}); }

const MeshIssue& Finding(const MeshCheckReport& report, const std::string& code) {
  const MeshIssue* issue = report.Find(code);
  if (!issue) {
    ADD_FAILURE() << "no finding " << code << " in\n" << report.FullReport();
    static const MeshIssue none;
    return none;
  }
  return *issue;
}

TEST(Mesh, TetCheckFindsNothingWrongWithAGrid) {
  const MeshCheckReport report = CheckTetMesh(Grid(), "grid");
  EXPECT_EQ(report.ExitCode(), 0) << report.FullReport();
  EXPECT_TRUE(report.issues.empty()) << report.FullReport();
  EXPECT_TRUE(report.is_tet);
}

TEST(Mesh, TetCheckNamesInvertedTets) {
  TetMesh mesh = Grid();
  std::swap(mesh.tets(7, 2), mesh.tets(7, 3));
  const MeshCheckReport report = CheckTetMesh(mesh, "grid");
  const MeshIssue& issue = Finding(report, "inverted-tets");
  EXPECT_EQ(issue.count, 1);
  EXPECT_NE(issue.examples[0].find("tetrahedron 7"), std::string::npos);
  EXPECT_NE(issue.fix.find("swap two vertices"), std::string::npos);
  EXPECT_EQ(report.ExitCode(), 1);
}

TEST(Mesh, TetCheckRecognisesTheOppositeOrientationConvention) {
  TetMesh mesh = Grid();
  mesh.tets.col(2).swap(mesh.tets.col(3));
  const MeshCheckReport report = CheckTetMesh(mesh, "grid");
  const MeshIssue& issue = Finding(report, "inverted-tets");
  EXPECT_EQ(issue.count, mesh.tets.rows());
  EXPECT_NE(issue.what.find("opposite vertex order"), std::string::npos);
}

TEST(Mesh, TetCheckFindsFlatRepeatedDuplicateAndOverlappingTets) {
  TetMesh mesh = Grid();
  const Eigen::Index t = mesh.tets.rows();
  const int v = static_cast<int>(mesh.vertices.rows());
  mesh.vertices.conservativeResize(v + 4, 3);
  // Four points in the plane z = 0, beside the grid: a flat tet.
  mesh.vertices.bottomRows(4) << 0.3, 0, 0, 0.4, 0, 0, 0.3, 0.1, 0, 0.4, 0.1, 0;
  mesh.tets.conservativeResize(t + 3, 4);
  mesh.tets.row(t) << v, v + 1, v + 2, v + 3;
  mesh.tets.row(t + 1) << 0, 0, 1, 5;
  mesh.tets.row(t + 2) = mesh.tets.row(2);
  const MeshCheckReport report = CheckTetMesh(mesh, "grid");
  EXPECT_EQ(Finding(report, "zero-volume-tets").count, 1);
  EXPECT_EQ(Finding(report, "repeated-vertex-in-tet").count, 1);
  EXPECT_EQ(Finding(report, "duplicate-tets").count, 1);
}

TEST(Mesh, TetCheckFindsAFaceSharedByThreeTets) {
  TetMesh mesh;
  mesh.vertices.resize(6, 3);
  mesh.vertices << 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.02, 0.02, 0.05, 0.03, 0.01, 0.04;
  mesh.tets.resize(3, 4);
  mesh.tets << 0, 1, 2, 3,  // the face (0, 1, 2) is in all three
      0, 1, 2, 4,           //
      0, 1, 2, 5;
  const MeshCheckReport report = CheckTetMesh(mesh, "overlap");
  EXPECT_EQ(Finding(report, "non-manifold-tet-faces").count, 1);
}

TEST(Mesh, TetCheckOfAFileNamesItsLines) {
  const std::string path = testing::MakeScratchDir("tet_check") + "/grid.node";
  TetMesh mesh = Grid();
  std::swap(mesh.tets(3, 0), mesh.tets(3, 1));
  WriteTetMesh(path, mesh);
  const MeshCheckReport tets = CheckMeshFile(path);
  EXPECT_EQ(tets.ExitCode(), 1);
  // The .ele file: a header line, then one line per tet; named, since the .node was checked.
  EXPECT_NE(tets.FullReport().find("tetrahedron 3 (line 5 of grid.ele)"), std::string::npos)
      << tets.FullReport();
  // Checked by its .ele, the tet's line needs no file name.
  const MeshCheckReport by_ele = CheckMeshFile(TetGenElePath(path));
  EXPECT_NE(by_ele.FullReport().find("tetrahedron 3 (line 5) "), std::string::npos)
      << by_ele.FullReport();
}

// Each file of a TetGen pair is named for its own lines, whichever of the two was checked.
TEST(Mesh, TetGenPairMessagesNameTheFileOfTheirLine) {
  const std::string dir = testing::MakeScratchDir("tetgen_names");
  TetMesh mesh = Grid();
  mesh.vertices(7, 0) = mesh.vertices(0, 0);  // vertex 7 now sits on vertex 0
  mesh.vertices(7, 1) = mesh.vertices(0, 1);
  mesh.vertices(7, 2) = mesh.vertices(0, 2);
  WriteTetMesh(dir + "/grid.node", mesh);
  // The .node line of a vertex, seen from the .ele (a header line, then node 1 on line 2).
  const std::string by_ele = CheckMeshFile(dir + "/grid.ele").FullReport();
  EXPECT_NE(by_ele.find("vertex 7 (line 9 of grid.node)"), std::string::npos) << by_ele;

  // A broken .ele, read through its .node: the error names the .ele and its line.
  std::ofstream(dir + "/bad.node") << "4 3 0 0\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n4 0 0 0.1\n";
  std::ofstream(dir + "/bad.ele") << "1 4 0\n1 1 2 3 x\n";
  const MeshCheckReport bad_ele = CheckMeshFile(dir + "/bad.node");
  EXPECT_EQ(bad_ele.ExitCode(), 2);
  EXPECT_NE(bad_ele.FullReport().find(dir + "/bad.ele:line 2: unusable: node number 'x'"),
            std::string::npos)
      << bad_ele.FullReport();
  EXPECT_NE(bad_ele.BriefReport().find("unusable: " + dir + "/bad.ele:line 2: "), std::string::npos)
      << bad_ele.BriefReport();

  // A broken .node, read through its .ele: the error names the .node.
  std::ofstream(dir + "/bad.node") << "4 3 0 0\n1 0 0 0\n2 0.1 0 nan\n3 0 0.1 0\n4 0 0 0.1\n";
  const std::string bad_node = CheckMeshFile(dir + "/bad.ele").FullReport();
  EXPECT_NE(bad_node.find(dir + "/bad.node:line 3: unusable:"), std::string::npos) << bad_node;
  EXPECT_NE(bad_node.find(dir + "/bad.ele: verdict: unusable"), std::string::npos) << bad_node;
}

}  // namespace
}  // namespace ergo
