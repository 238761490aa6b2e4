// Reader features that real files use: OBJ corner syntax and negative indices, OFF header
// variants and wrapped faces, PLY types and byte orders, STL flavours, gmsh versions and
// higher-order elements, TetGen numbering. And refusals that must name the line and the fix.

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

std::string WriteFile(const std::string& name, const std::string& content) {
  static const std::string dir = testing::MakeScratchDir("mesh_readers");
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The InputError message of `read`, or "" when it does not throw.
std::string ErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

bool HasNote(const ReadDetails& details, const std::string& text) {
  for (const ReadNote& note : details.notes) {
    if (note.what.find(text) != std::string::npos) return true;
  }
  return false;
}

template <typename T>
std::string LittleEndian(T value) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  return bytes;
}

template <typename T>
std::string BigEndian(T value) {
  std::string bytes = LittleEndian(value);
  return std::string(bytes.rbegin(), bytes.rend());
}

TEST(Mesh, ObjReadsCornerSyntaxNegativeIndicesAndSplitsPolygons) {
  const std::string path = WriteFile("features.obj",
                                     "mtllib x.mtl\no thing\ng group\nv 0 0 0\nv 1 0 0\n"
                                     "v 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                     "usemtl red\ns 1\nf 1/1/1 2/1/1 3/1/1\n"
                                     "f -4//1 -2//1 -1//1\nl 1 2\n"
                                     "f 1/1 2/1 3/1 4/1  # a quad\n");
  ReadDetails details;
  const TriMesh mesh = ReadTriMesh(path, {}, &details);
  ASSERT_EQ(mesh.vertices.rows(), 4);
  ASSERT_EQ(mesh.triangles.rows(), 4);
  EXPECT_EQ(mesh.triangles.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(mesh.triangles.row(2), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles.row(3), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(details.element_lines[3], 15);
  EXPECT_TRUE(HasNote(details, "split into triangles"));
  EXPECT_TRUE(HasNote(details, "line ('l')"));
}

TEST(Mesh, ObjJoinsBackslashContinuedLinesAndForwardReferences) {
  const std::string path = WriteFile("continued.obj", "f 1 2 \\\n 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const TriMesh mesh = ReadTriMesh(path);
  EXPECT_EQ(mesh.triangles.rows(), 1);
  EXPECT_EQ(mesh.triangles.row(0), Eigen::RowVector3i(0, 1, 2));
}

TEST(Mesh, ObjRefusesBadIndicesNamingTheLine) {
  const std::string base = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_NE(ErrorOf([&] {
              ReadTriMesh(WriteFile("big.obj", base + "f 1 2 4\n"));
            }).find("big.obj:line 4: face refers to vertex 4, but the file has 3 vertices"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf([&] { ReadTriMesh(WriteFile("neg.obj", base + "f -1 -2 -4\n")); }).find("line 4"),
      std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              ReadTriMesh(WriteFile("slash.obj", base + "f /1 2 3\n"));
            }).find("does not start with a vertex index"),
            std::string::npos);
}

TEST(Mesh, OffReadsHeaderVariantsCommentsAndWrappedColouredFaces) {
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string variants[] = {
      "OFF\n4 4 6\n" + points + faces,
      "\xEF\xBB\xBF# comment\nOFF 4 4 0\n\n# vertices\n" + points + faces,
      "NOFF\r\n4 4 0\r\n0 0 0 0 0 1\r\n1 0 0 0 0 1\r\n0 1 0 0 0 1\r\n0 0 1 0 0 1\r\n" + faces,
      "COFF\n4 4 0\n" + points + "3 0 2 1 255 0 0\n3 0 1\n 3 0.5 0.5 0.5\n3 0 3 2\n3 1 2 3\n",
      "  OFF4 4 0\n" + points + faces,
      "4 4 0\n" + points + faces,
  };
  int index = 0;
  for (const std::string& text : variants) {
    SCOPED_TRACE(index);
    const TriMesh mesh = ReadTriMesh(WriteFile("variant" + std::to_string(index++) + ".off", text));
    ASSERT_EQ(mesh.vertices.rows(), 4);
    ASSERT_EQ(mesh.triangles.rows(), 4);
    EXPECT_EQ(mesh.triangles.row(1), Eigen::RowVector3i(0, 1, 3));
    EXPECT_EQ(mesh.vertices(3, 2), 1.0);
  }
}

TEST(Mesh, OffRefusesUnsupportedVariantsWithAFix) {
  EXPECT_NE(
      ErrorOf([] { ReadTriMesh(WriteFile("four.off", "4OFF\n1 0 0\n0 0 0 0\n")); }).find("4-D"),
      std::string::npos);
  EXPECT_NE(ErrorOf([] { ReadTriMesh(WriteFile("bin.off", "OFF BINARY\n")); }).find("binary OFF"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              ReadTriMesh(WriteFile("zero.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n"));
            }).find("face 0 has 0 vertices"),
            std::string::npos);
}

TEST(Mesh, PlyReadsBigEndianWithMixedTypesAndExtraElements) {
  std::string data =
      "ply\r\nformat binary_big_endian 1.0\r\ncomment made by hand\r\nobj_info test\r\n"
      "element vertex 4\r\nproperty uchar flags\r\nproperty double x\r\nproperty float y\r\n"
      "property short z\r\nproperty list uchar float uv\r\n"
      "element face 2\r\nproperty list uint short vertex_index\r\nproperty int material\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n";
  const double xs[] = {0.0, 1.5, 0.0, 0.0};
  const float ys[] = {0.0f, 0.0f, 2.25f, 0.0f};
  const int16_t zs[] = {0, 0, 0, 3};
  for (int v = 0; v < 4; ++v) {
    data += '\x07' + BigEndian(xs[v]) + BigEndian(ys[v]) + BigEndian(zs[v]);
    data += '\x01' + BigEndian(0.5f);  // a one-entry list, skipped
  }
  data += BigEndian(uint32_t{3}) + BigEndian(int16_t{0}) + BigEndian(int16_t{2}) +
          BigEndian(int16_t{1}) + BigEndian(int32_t{9});
  data += BigEndian(uint32_t{4}) + BigEndian(int16_t{0}) + BigEndian(int16_t{1}) +
          BigEndian(int16_t{3}) + BigEndian(int16_t{2}) + BigEndian(int32_t{9});
  data += BigEndian(int32_t{0}) + BigEndian(int32_t{1});
  ReadDetails details;
  const TriMesh mesh = ReadTriMesh(WriteFile("big_endian.ply", data), {}, &details);
  ASSERT_EQ(mesh.vertices.rows(), 4);
  ASSERT_EQ(mesh.triangles.rows(), 3);
  EXPECT_EQ(mesh.vertices.row(1), Eigen::RowVector3d(1.5, 0, 0));
  EXPECT_EQ(mesh.vertices.row(2), Eigen::RowVector3d(0, 2.25, 0));
  EXPECT_EQ(mesh.vertices.row(3), Eigen::RowVector3d(0, 0, 3));
  EXPECT_EQ(mesh.triangles.row(2), Eigen::RowVector3i(0, 3, 2));
  EXPECT_EQ(details.format, "PLY binary big-endian");
  EXPECT_TRUE(HasNote(details, "'edge'"));
}

TEST(Mesh, PlyAsciiToleratesExtraValuesButNotMissingOnes) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  ReadDetails details;
  const TriMesh mesh = ReadTriMesh(
      WriteFile("extra.ply", header + "0 0 0\n1 0 0 9 9\n0 1 0\n3 0 1 2 7\n"), {}, &details);
  EXPECT_EQ(mesh.triangles.rows(), 1);
  ASSERT_FALSE(details.notes.empty());
  EXPECT_TRUE(details.notes[0].is_problem);
  EXPECT_EQ(details.notes[0].location, "line 11");
  EXPECT_NE(ErrorOf([&] {
              ReadTriMesh(WriteFile("short.ply", header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"));
            }).find("short.ply:line 11: 'vertex' record 1 has only 2 values"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              ReadTriMesh(WriteFile("index.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
            }).find("line 13: face 0 refers to vertex 3"),
            std::string::npos);
}

TEST(Mesh, StlAsciiReadsMixedCaseAndSeveralSolidsAndWelds) {
  const std::string facet =
      "  FACET NORMAL 0 0 1\n    Outer Loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
      "      vertex 0 1 0\n    EndLoop\n  EndFacet\n";
  const std::string second =
      "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
      "endloop\nendfacet\n";
  const TriMesh mesh =
      ReadTriMesh(WriteFile("two.stl", "SOLID first part\n" + facet + "ENDSOLID first\nsolid b\n" +
                                           second + "endsolid b\n"));
  EXPECT_EQ(mesh.vertices.rows(), 4);  // the shared corners were welded
  EXPECT_EQ(mesh.triangles.rows(), 2);
  EXPECT_EQ(mesh.triangles.row(1), Eigen::RowVector3i(1, 3, 2));
}

TEST(Mesh, StlBinaryWithSolidHeaderIsReadAsBinary) {
  std::string data = "solid this header lies";
  data.resize(80, ' ');
  data += LittleEndian(uint32_t{1});
  for (float value : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    data += LittleEndian(value);
  }
  data += std::string(2, '\0');
  ReadDetails details;
  const TriMesh mesh = ReadTriMesh(WriteFile("solid_binary.stl", data), {}, &details);
  EXPECT_EQ(details.format, "STL binary");
  EXPECT_EQ(mesh.triangles.rows(), 1);
  EXPECT_EQ(mesh.vertices(2, 1), 1.0);
}

TEST(Mesh, MshV2ReadsTet10CornersAndSkipsOtherSections) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"body\"\n$EndPhysicalNames\n"
      "$Nodes\n10\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 .5 0 0\n6 .5 .5 0\n7 0 .5 0\n"
      "8 0 0 .5\n9 0 .5 .5\n10 .5 0 .5\n$EndNodes\n$Elements\n2\n"
      "1 15 2 0 1 1\n2 11 2 1 1 1 2 3 4 5 6 7 8 9 10\n$EndElements\n"
      "$NodeData\n1\n\"t\"\n$EndNodeData\n";
  ReadDetails details;
  const TetMesh mesh = ReadTetMesh(WriteFile("tet10.msh", text), {}, &details);
  ASSERT_EQ(mesh.tets.rows(), 1);
  EXPECT_EQ(mesh.vertices.rows(), 4);  // mid-edge nodes dropped
  EXPECT_EQ(mesh.tets.row(0), Eigen::RowVector4i(0, 1, 2, 3));
  EXPECT_TRUE(HasNote(details, "10-node tet"));
  EXPECT_TRUE(HasNote(details, "1 point"));
  EXPECT_EQ(details.element_lines[0], 24);
}

TEST(Mesh, MshV40AndV41SurfacesAreReadAsTriangles) {
  const std::string v40 =
      "$MeshFormat\n4 0 8\n$EndMeshFormat\n$Nodes\n2 4\n1 2 0 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
      "1 1 1 1\n4 1 1 0 0.5\n$EndNodes\n$Elements\n2 2\n1 2 2 1\n1 1 2 3\n2 2 3 1\n"
      "2 1 2 4 3\n$EndElements\n";
  const std::string v41 =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 1 1 0 0 0\n"
      "$EndEntities\n$Nodes\n2 4 1 4\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n"
      "1 1 1 1\n4\n1 1 0 0.5\n$EndNodes\n$Elements\n2 2 1 2\n2 1 2 1\n1 1 2 3\n"
      "2 1 3 1\n2 1 2 4 3\n$EndElements\n";
  for (const auto& [name, text] : {std::pair{"v40.msh", v40}, std::pair{"v41.msh", v41}}) {
    SCOPED_TRACE(name);
    ReadDetails details;
    const TriMesh mesh = ReadTriMesh(WriteFile(name, text), {}, &details);
    ASSERT_EQ(mesh.triangles.rows(), 3);
    EXPECT_EQ(mesh.vertices.rows(), 4);
    EXPECT_EQ(mesh.vertices(3, 0), 1.0);
    EXPECT_EQ(mesh.triangles.row(2), Eigen::RowVector3i(0, 3, 2));
    EXPECT_TRUE(HasNote(details, "quad was split"));
    EXPECT_NE(ErrorOf([&] { ReadTetMesh(WriteFile(name, text)); }).find("no tetrahedra"),
              std::string::npos);
  }
}

TEST(Mesh, MshV2BinaryIsReadInEitherByteOrder) {
  for (bool big : {false, true}) {
    auto i32 = [big](int32_t v) { return big ? BigEndian(v) : LittleEndian(v); };
    auto f64 = [big](double v) { return big ? BigEndian(v) : LittleEndian(v); };
    std::string data = "$MeshFormat\n2.2 1 8\n" + i32(1) + "\n$EndMeshFormat\n$Nodes\n4\n";
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int n = 0; n < 4; ++n)
      data += i32(n + 1) + f64(xyz[n][0]) + f64(xyz[n][1]) + f64(xyz[n][2]);
    data += "$EndNodes\n$Elements\n1\n" + i32(4) + i32(1) + i32(2) + i32(1) + i32(0) + i32(1) +
            i32(1) + i32(2) + i32(3) + i32(4) + "\n$EndElements\n";
    const TetMesh mesh = ReadTetMesh(WriteFile(big ? "be.msh" : "le.msh", data));
    ASSERT_EQ(mesh.tets.rows(), 1);
    EXPECT_EQ(mesh.vertices(3, 2), 1.0);
  }
}

TEST(Mesh, MshRefusesOldAndBinaryV4WithAConversionCommand) {
  EXPECT_NE(ErrorOf([] {
              ReadTetMesh(WriteFile("old.msh", "$NOD\n1\n1 0 0 0\n$ENDNOD\n"));
            }).find("gmsh FILE -0 -format msh41"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              ReadTetMesh(WriteFile("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"));
            }).find("MSH 3.0"),
            std::string::npos);
}

TEST(Mesh, TetGenReadsZeroBasedFilesWithAttributesAndMarkers) {
  WriteFile("zero.node",
            "# nodes\n4 3 1 1\n0 0 0 0 7.5 1\n1 1 0 0 7.5 1\n2 0 1 0 7.5 1\n3 0 0 1 7.5 0\n");
  WriteFile("zero.ele", "1 4 1\n0 0 1 2 3 2.0  # one tet\n");
  ReadDetails details;
  const TetMesh mesh =
      ReadTetMesh(WriteFile("zero.ele", "1 4 1\n0 0 1 2 3 2.0  # one tet\n"), {}, &details);
  EXPECT_EQ(mesh.tets.row(0), Eigen::RowVector4i(0, 1, 2, 3));
  EXPECT_EQ(mesh.vertices(1, 0), 1.0);
  EXPECT_EQ(details.format, "TetGen .node/.ele (0-based)");
}

TEST(Mesh, TetGenRefusesTriangleProgramFilesAndMissingPartners) {
  WriteFile("flat.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
  WriteFile("flat.ele", "1 3 0\n1 1 2 3\n");
  const std::string error = ErrorOf([] { ReadTetMesh(WriteFile("flat.ele", "1 3 0\n1 1 2 3\n")); });
  EXPECT_NE(error.find("flat.node:line 1: the file has dimension 2"), std::string::npos) << error;
  EXPECT_NE(error.find("Triangle program"), std::string::npos) << error;
  EXPECT_NE(ErrorOf([] {
              ReadTetMesh(WriteFile("alone.node", "1 3 0 0\n1 0 0 0\n"));
            }).find("alone.ele: the file does not exist"),
            std::string::npos);
}

TEST(Mesh, ReadersNeverAllocateFromHugeHeaderCounts) {
  const std::string cases[][2] = {
      {"huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n"},
      {"huge.ply",
       "ply\nformat ascii 1.0\nelement vertex 2147483000\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n0 0 0\n"},
      {"huge.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2000000000\n1 0 0 0\n"},
      {"huge41.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2000000000 1 2\n"},
      {"huge.node", "2000000000 3 0 0\n1 0 0 0\n"},
  };
  for (const auto& [name, text] : cases) {
    const std::string path = WriteFile(name, text);
    EXPECT_NE(
        ErrorOf([&] { ReadAnyMesh(path); }).find("the count is wrong or the file is truncated"),
        std::string::npos)
        << name << ": " << ErrorOf([&] { ReadAnyMesh(path); });
  }
}

TEST(Mesh, ReadersRefuseOverlongLinesMissingFilesAndUnknownExtensions) {
  EXPECT_NE(ErrorOf([] {
              ReadTriMesh(WriteFile("long.obj", "v " + std::string(2 << 20, '1')));
            }).find("longer than 1 MiB"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ReadTriMesh("/nonexistent/ergo/mesh.obj"); }).find("does not exist"),
            std::string::npos);
  const std::string folder = testing::MakeScratchDir("dir") + "/folder.obj";
  std::filesystem::create_directories(folder);
  EXPECT_NE(ErrorOf([&] { ReadTriMesh(folder); }).find("directory"), std::string::npos);
  EXPECT_NE(ErrorOf([] { ReadTriMesh(WriteFile("mesh.vrml", "x")); }).find("'.vrml'"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ReadTriMesh(WriteFile("mesh.node", "x")); }).find("tetrahedral"),
            std::string::npos);
}

}  // namespace
}  // namespace ergo
