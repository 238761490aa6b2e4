// The VTU writer: read the file back with a minimal parser of the VTK XML layout and check
// the structure (counts, cell types, offsets) and every value of every field.

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/vtu_writer.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

struct VtuFile {
  std::string text;
  // DataArray contents by Name (points under "Points").
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, int> components;
};

std::string Attribute(const std::string& tag, const std::string& name) {
  const size_t at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const size_t start = at + name.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

VtuFile ReadVtu(const std::string& path) {
  VtuFile file;
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  file.text = buffer.str();
  size_t at = 0;
  bool in_points = false;
  while ((at = file.text.find('<', at)) != std::string::npos) {
    const size_t end = file.text.find('>', at);
    const std::string tag = file.text.substr(at, end - at + 1);
    if (tag.rfind("<Points", 0) == 0) in_points = true;
    if (tag.rfind("</Points", 0) == 0) in_points = false;
    if (tag.rfind("<DataArray", 0) == 0) {
      const std::string name = in_points ? "Points" : Attribute(tag, "Name");
      const std::string components = Attribute(tag, "NumberOfComponents");
      file.components[name] = components.empty() ? 1 : std::stoi(components);
      const size_t close = file.text.find("</DataArray>", end);
      std::istringstream values(file.text.substr(end + 1, close - end - 1));
      double value;
      while (values >> value) file.arrays[name].push_back(value);
    }
    at = end;
  }
  return file;
}

TEST(Mesh, VtuTriangleMeshCarriesNamedPointAndCellFields) {
  const TriMesh mesh = MakeIcosphere(0.1, 1);
  VtuFields fields;
  fields.point_scalars.push_back({"pressure \"Pa\"", mesh.vertices.col(2) * 1e3});
  fields.point_vectors.push_back({"displacement", mesh.vertices * 0.01});
  Eigen::VectorXd cell_ids =
      Eigen::VectorXd::LinSpaced(mesh.triangles.rows(), 0, mesh.triangles.rows() - 1);
  fields.cell_scalars.push_back({"id", cell_ids});
  Eigen::Matrix<double, Eigen::Dynamic, 3> normals(mesh.triangles.rows(), 3);
  normals.setConstant(1.0 / 3.0);
  fields.cell_vectors.push_back({"normal", normals});
  const std::string path = testing::MakeScratchDir("vtu") + "/sphere.vtu";
  WriteVtu(path, mesh, fields);

  const VtuFile file = ReadVtu(path);
  EXPECT_NE(file.text.find("NumberOfPoints=\"42\" NumberOfCells=\"80\""), std::string::npos);
  EXPECT_NE(file.text.find("Name=\"pressure &quot;Pa&quot;\""), std::string::npos);
  ASSERT_EQ(file.arrays.at("Points").size(), 3u * 42);
  EXPECT_EQ(file.arrays.at("Points")[3 * 7 + 1], mesh.vertices(7, 1));
  ASSERT_EQ(file.arrays.at("pressure &quot;Pa&quot;").size(), 42u);
  EXPECT_EQ(file.arrays.at("pressure &quot;Pa&quot;")[5], mesh.vertices(5, 2) * 1e3);
  EXPECT_EQ(file.components.at("displacement"), 3);
  EXPECT_EQ(file.arrays.at("displacement")[3 * 4 + 2], mesh.vertices(4, 2) * 0.01);
  EXPECT_EQ(file.arrays.at("id")[79], 79.0);
  EXPECT_EQ(file.arrays.at("normal")[3 * 10], 1.0 / 3.0);
  ASSERT_EQ(file.arrays.at("connectivity").size(), 3u * 80);
  EXPECT_EQ(file.arrays.at("connectivity")[3 * 9 + 2], mesh.triangles(9, 2));
  EXPECT_EQ(file.arrays.at("offsets").back(), 240.0);
  for (double type : file.arrays.at("types")) EXPECT_EQ(type, 5.0);  // VTK_TRIANGLE
}

TEST(Mesh, VtuTetMeshUsesTetraCells) {
  const TetMesh mesh = MakeTetGrid({0, 0, 0}, {1, 1, 1}, {1, 1, 2});
  VtuFields fields;
  fields.cell_scalars.push_back({"E", Eigen::VectorXd::Constant(mesh.tets.rows(), 1e4)});
  const std::string path = testing::MakeScratchDir("vtu") + "/grid.vtu";
  WriteVtu(path, mesh, fields);
  const VtuFile file = ReadVtu(path);
  ASSERT_EQ(file.arrays.at("types").size(), static_cast<size_t>(mesh.tets.rows()));
  for (double type : file.arrays.at("types")) EXPECT_EQ(type, 10.0);  // VTK_TETRA
  EXPECT_EQ(file.arrays.at("offsets")[1], 8.0);
  EXPECT_EQ(file.arrays.at("connectivity")[4 * 3 + 1], mesh.tets(3, 1));
  EXPECT_EQ(file.arrays.at("E").size(), static_cast<size_t>(mesh.tets.rows()));
}

TEST(Mesh, VtuFieldOfTheWrongSizeIsAProgrammingError) {
  const TriMesh mesh = MakeIcosphere(0.1, 0);
  VtuFields fields;
  fields.point_scalars.push_back({"short", Eigen::VectorXd::Zero(3)});
  const std::string path = testing::MakeScratchDir("vtu") + "/bad.vtu";
  EXPECT_DEATH(WriteVtu(path, mesh, fields), "wrong number of rows");
}

}  // namespace
}  // namespace ergo
