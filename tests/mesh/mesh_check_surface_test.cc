// The surface checks on meshes built in memory: a clean closed sphere passes, and each
// defect, made on purpose, is found, counted, located and given a fix.

#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

MeshCheckOptions Closed() {
  MeshCheckOptions options;
  options.require_closed = true;
  return options;
}

// The finding `code` of `report`, failing the test when it is missing.
const MeshIssue& Finding(const MeshCheckReport& report, const std::string& code) {
  const MeshIssue* issue = report.Find(code);
  if (!issue) {
    ADD_FAILURE() << "no finding " << code << " in\n" << report.FullReport();
    static const MeshIssue none;
    return none;
  }
  return *issue;
}

TriMesh Sphere() { return MakeIcosphere(0.1, 2); }

TEST(Mesh, CheckFindsNothingWrongWithAClosedSphere) {
  const MeshCheckReport report = CheckTriMesh(Sphere(), "sphere", Closed());
  EXPECT_EQ(report.ExitCode(), 0) << report.FullReport();
  EXPECT_TRUE(report.issues.empty()) << report.FullReport();
  EXPECT_NEAR(report.bounding_box_diagonal, 0.2 * std::sqrt(3.0), 0.02);
}

TEST(Mesh, CheckReportsAHoleOnlyWhenAClosedSurfaceIsRequired) {
  TriMesh mesh = Sphere();
  mesh.triangles.conservativeResize(mesh.triangles.rows() - 1, 3);
  const MeshCheckReport open_ok = CheckTriMesh(mesh, "holed");
  EXPECT_EQ(open_ok.ExitCode(), 0);
  EXPECT_EQ(Finding(open_ok, "open-boundary").severity, Severity::kNote);
  const MeshCheckReport closed = CheckTriMesh(mesh, "holed", Closed());
  EXPECT_EQ(closed.ExitCode(), 1);
  const MeshIssue& hole = Finding(closed, "open-boundary");
  EXPECT_EQ(hole.count, 3);
  EXPECT_FALSE(hole.fix.empty());
}

TEST(Mesh, CheckReportsAFlippedFaceAsInconsistentOrientation) {
  TriMesh mesh = Sphere();
  std::swap(mesh.triangles(17, 1), mesh.triangles(17, 2));
  const MeshCheckReport report = CheckTriMesh(mesh, "flipped", Closed());
  EXPECT_EQ(report.ExitCode(), 1);
  const MeshIssue& issue = Finding(report, "inconsistent-orientation");
  EXPECT_EQ(issue.count, 3);
  ASSERT_FALSE(issue.examples.empty());
  EXPECT_NE(issue.examples[0].find("triangle 17"), std::string::npos) << issue.examples[0];
}

TEST(Mesh, CheckReportsAnInsideOutSurface) {
  TriMesh mesh = Sphere();
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  const MeshCheckReport report = CheckTriMesh(mesh, "inside_out", Closed());
  EXPECT_EQ(Finding(report, "inward-orientation").count, 1);
  EXPECT_EQ(report.Find("inconsistent-orientation"), nullptr);
}

TEST(Mesh, CheckReportsCoincidentVerticesAsCracks) {
  TriMesh mesh = Sphere();
  const Eigen::Index copy = mesh.vertices.rows();
  mesh.vertices.conservativeResize(copy + 1, 3);
  mesh.vertices.row(copy) = mesh.vertices.row(mesh.triangles(0, 0));
  mesh.triangles(0, 0) = static_cast<int>(copy);
  const MeshCheckReport report = CheckTriMesh(mesh, "cracked", Closed());
  const MeshIssue& issue = Finding(report, "coincident-vertices");
  EXPECT_EQ(issue.count, 1);
  EXPECT_NE(issue.examples[0].find("vertex " + std::to_string(copy)), std::string::npos);
  EXPECT_EQ(Finding(report, "open-boundary").count, 4);  // two edges on each side of the crack
  // Welded for the CGAL test, the crack is no self-intersection.
  EXPECT_EQ(report.Find("self-intersections"), nullptr) << report.FullReport();
}

TEST(Mesh, CheckReportsNonManifoldEdgesAndVertices) {
  // Two tetrahedra sharing an edge, and two sharing only a vertex.
  TriMesh edge_pair;
  edge_pair.vertices.resize(6, 3);
  edge_pair.vertices << 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, -0.1, 0, 0, 0, -0.1;
  edge_pair.triangles.resize(8, 3);
  edge_pair.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,  //
      0, 1, 4, 0, 5, 1, 0, 4, 5, 1, 5, 4;
  const MeshCheckReport edges = CheckTriMesh(edge_pair, "edge_pair", Closed());
  EXPECT_EQ(Finding(edges, "non-manifold-edges").count, 1);
  EXPECT_NE(Finding(edges, "self-intersection-not-checked").what.find("not a manifold"),
            std::string::npos);

  TriMesh vertex_pair;
  vertex_pair.vertices.resize(7, 3);
  vertex_pair.vertices << 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, -0.1, 0, 0, 0, -0.1, 0, 0, 0,
      -0.1;
  vertex_pair.triangles.resize(8, 3);
  vertex_pair.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,  //
      0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5;
  const MeshCheckReport vertices = CheckTriMesh(vertex_pair, "vertex_pair", Closed());
  const MeshIssue& pinched = Finding(vertices, "non-manifold-vertices");
  EXPECT_EQ(pinched.count, 1);
  EXPECT_NE(pinched.examples[0].find("vertex 0"), std::string::npos);
  EXPECT_EQ(vertices.Find("non-manifold-edges"), nullptr);
}

TEST(Mesh, CheckReportsDegenerateRepeatedAndDuplicateFaces) {
  TriMesh mesh = Sphere();
  const Eigen::Index f = mesh.triangles.rows();
  const Eigen::Index v = mesh.vertices.rows();
  mesh.vertices.conservativeResize(v + 1, 3);
  // A new vertex halfway along an edge of triangle 0: the triangle (a, mid, b) is flat.
  mesh.vertices.row(v) =
      0.5 * (mesh.vertices.row(mesh.triangles(0, 0)) + mesh.vertices.row(mesh.triangles(0, 1)));
  mesh.triangles.conservativeResize(f + 3, 3);
  mesh.triangles.row(f) << mesh.triangles(0, 0), static_cast<int>(v), mesh.triangles(0, 1);
  mesh.triangles.row(f + 1) << 3, 3, 4;
  mesh.triangles.row(f + 2) = mesh.triangles.row(5);
  const MeshCheckReport report = CheckTriMesh(mesh, "faulty", Closed());
  EXPECT_EQ(Finding(report, "degenerate-triangles").count, 1);
  EXPECT_EQ(Finding(report, "repeated-vertex-in-face").count, 1);
  const MeshIssue& duplicate = Finding(report, "duplicate-faces");
  EXPECT_EQ(duplicate.count, 1);
  EXPECT_NE(duplicate.examples[0].find("repeats triangle 5"), std::string::npos);
}

TEST(Mesh, CheckFindsSelfIntersectionsOfOverlappingSpheres) {
  const TriMesh a = MakeIcosphere(0.1, 2);
  const TriMesh b = MakeIcosphere(0.1, 2, Eigen::Vector3d(0.05, 0.02, 0.01));
  TriMesh both;
  both.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  both.vertices << a.vertices, b.vertices;
  both.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  both.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.rows()));
  const MeshCheckReport report = CheckTriMesh(both, "overlap", Closed());
  const MeshIssue& issue = Finding(report, "self-intersections");
  EXPECT_GT(issue.count, 10);
  EXPECT_LE(static_cast<int>(issue.examples.size()), 5);
  EXPECT_EQ(report.ExitCode(), 1);
}

TEST(Mesh, CheckFlagsSizesThatSuggestTheWrongUnit) {
  TriMesh mesh = Sphere();
  mesh.vertices *= 1000;  // a 10 cm sphere written in millimetres, read as metres
  const MeshCheckReport large = CheckTriMesh(mesh, "mm_as_m");
  EXPECT_NE(Finding(large, "size-too-large").fix.find("--unit=mm"), std::string::npos);
  mesh.vertices *= 1e-6;
  const MeshCheckReport small = CheckTriMesh(mesh, "tiny");
  EXPECT_NE(Finding(small, "size-too-small").what.find("smaller than 1 cm"), std::string::npos);
  // Read with the right unit, the same file is fine.
  const std::string path = testing::MakeScratchDir("check_unit") + "/sphere_mm.off";
  WriteOptions write;
  write.unit = LengthUnit::kMillimetre;
  WriteTriMesh(path, Sphere(), write);
  MeshCheckOptions options = Closed();
  EXPECT_EQ(CheckMeshFile(path, options).ExitCode(), 1);
  options.unit = LengthUnit::kMillimetre;
  EXPECT_EQ(CheckMeshFile(path, options).ExitCode(), 0);
}

TEST(Mesh, CheckNotesUnreferencedVerticesAndSurvivesBadInMemoryMeshes) {
  TriMesh mesh = Sphere();
  mesh.vertices.conservativeResize(mesh.vertices.rows() + 2, 3);
  mesh.vertices.bottomRows(2).setConstant(0.05);
  const MeshCheckReport report = CheckTriMesh(mesh, "extra", Closed());
  EXPECT_EQ(Finding(report, "unreferenced-vertices").count, 2);
  EXPECT_EQ(report.ExitCode(), 0);

  TriMesh broken = Sphere();
  broken.triangles(3, 1) = 100000;
  EXPECT_EQ(CheckTriMesh(broken, "broken").ExitCode(), 2);
  broken = Sphere();
  broken.vertices(2, 0) = std::nan("");
  EXPECT_EQ(CheckTriMesh(broken, "nan").ExitCode(), 2);
}

TEST(Mesh, CheckReportNamesFileElementLineAndFix) {
  const std::string path = testing::MakeScratchDir("check_report") + "/flipped.obj";
  TriMesh mesh = Sphere();
  std::swap(mesh.triangles(4, 1), mesh.triangles(4, 2));
  WriteTriMesh(path, mesh);
  const MeshCheckReport report = CheckMeshFile(path, Closed());
  const std::string text = report.FullReport();
  // Line of triangle 4 in the OBJ: one comment line, then vertices, then faces.
  const std::string line = "line " + std::to_string(1 + mesh.vertices.rows() + 5);
  EXPECT_NE(text.find(path + ": edge"), std::string::npos) << text;
  EXPECT_NE(text.find("triangle 4 (" + line + ")"), std::string::npos) << text;
  EXPECT_NE(text.find("fix: orient the faces consistently"), std::string::npos) << text;
  EXPECT_NE(text.find("verdict: problems found (exit 1)"), std::string::npos) << text;
  EXPECT_NE(report.BriefReport().find("inconsistent-orientation"), std::string::npos);
}

TEST(Mesh, SupportSphereDataFileIsTheCleanGeneratedIcosphere) {
  const std::string path = testing::SourcePath("data/meshes/support_sphere.off");
  const TriMesh expected = MakeIcosphere(0.1, 3);
  const TriMesh stored = ReadTriMesh(path);
  EXPECT_TRUE(stored.vertices == expected.vertices);
  EXPECT_TRUE(stored.triangles == expected.triangles);
  EXPECT_EQ(CheckMeshFile(path, Closed()).ExitCode(), 0);
}

}  // namespace
}  // namespace ergo
