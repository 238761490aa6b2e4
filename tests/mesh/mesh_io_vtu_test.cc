// The VTU writer: read the file back with a minimal parser of the VTK XML layout — the text
// of ASCII arrays, or the appended raw block of binary ones (each array's UInt64 byte count,
// then its bytes) — and check the structure (counts, cell types, offsets) and every value of
// every field, bit for bit. Then the binary file once more through meshio, an independent
// reader (skipped where Debian's python3-meshio is missing).

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/vtu_writer.h"
#include "tests/support/test_paths.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

// Debian's python3, where python3-meshio installs (a pyenv or venv python3 earlier on the
// PATH usually lacks it).
constexpr char kSystemPython[] = "/usr/bin/python3";

struct VtuArray {
  std::string type;    // Float64, Int64, UInt8
  std::string format;  // ascii or appended
  int components = 1;
  std::vector<double> text_values;  // ascii
  std::string bytes;                // appended: the raw values after the byte count
};

struct VtuFile {
  std::string text;    // the whole file
  std::string header;  // the XML before the appended data (the whole file for ASCII)
  // DataArrays by Name (the points under "Points").
  std::map<std::string, VtuArray> arrays;
};

std::string Attribute(const std::string& tag, const std::string& name) {
  const size_t at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const size_t start = at + name.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

VtuFile ReadVtu(const std::string& path) {
  VtuFile file;
  file.text = ReadFile(path);
  // Binary: the XML ends at <AppendedData encoding="raw">; the block starts after its '_'.
  const std::string appended_tag = "<AppendedData encoding=\"raw\">";
  const size_t appended_at = file.text.find(appended_tag);
  size_t block = std::string::npos;
  if (appended_at != std::string::npos) {
    file.header = file.text.substr(0, appended_at);
    block = file.text.find('_', appended_at + appended_tag.size()) + 1;
  } else {
    file.header = file.text;
  }
  const std::string& xml = file.header;
  size_t at = 0;
  bool in_points = false;
  while ((at = xml.find('<', at)) != std::string::npos) {
    const size_t end = xml.find('>', at);
    const std::string tag = xml.substr(at, end - at + 1);
    if (tag.rfind("<Points", 0) == 0) in_points = true;
    if (tag.rfind("</Points", 0) == 0) in_points = false;
    if (tag.rfind("<DataArray", 0) == 0) {
      const std::string name = in_points ? "Points" : Attribute(tag, "Name");
      VtuArray& array = file.arrays[name];
      array.type = Attribute(tag, "type");
      array.format = Attribute(tag, "format");
      const std::string components = Attribute(tag, "NumberOfComponents");
      array.components = components.empty() ? 1 : std::stoi(components);
      if (array.format == "appended") {
        EXPECT_NE(block, std::string::npos) << name << ": appended array without AppendedData";
        const size_t offset = block + std::stoull(Attribute(tag, "offset"));
        std::uint64_t count = 0;
        EXPECT_LE(offset + sizeof count, file.text.size()) << name;
        std::memcpy(&count, file.text.data() + offset, sizeof count);
        EXPECT_LE(offset + sizeof count + count, file.text.size()) << name;
        array.bytes = file.text.substr(offset + sizeof count, count);
      } else {
        const size_t close = xml.find("</DataArray>", end);
        std::istringstream values(xml.substr(end + 1, close - end - 1));
        double value;
        while (values >> value) array.text_values.push_back(value);
      }
    }
    at = end;
  }
  return file;
}

// The raw bytes of `values`, row after row, as T: what the binary file must hold.
template <typename T, typename Matrix>
std::string RowMajorBytes(const Matrix& values) {
  std::string bytes;
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    for (Eigen::Index k = 0; k < values.cols(); ++k) {
      const T value = static_cast<T>(values(i, k));
      bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
  }
  return bytes;
}

template <typename T>
std::string Bytes(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A field per kind, with values that need all 17 digits (1/3, π multiples, tiny and huge).
VtuFields SampleFields(const Vertices& vertices, Eigen::Index cells) {
  VtuFields fields;
  fields.point_scalars.push_back({"pressure \"Pa\"", vertices.col(2) * (1e3 / 3.0)});
  fields.point_vectors.push_back({"displacement", vertices * 0.01 + vertices.cwiseAbs2() * 1e-300});
  fields.cell_scalars.push_back(
      {"id", Eigen::VectorXd::LinSpaced(cells, 0, static_cast<double>(cells - 1)) * M_PI});
  Eigen::Matrix<double, Eigen::Dynamic, 3> normals(cells, 3);
  for (Eigen::Index c = 0; c < cells; ++c) normals.row(c) << 1.0 / 3.0, -2e200 / (c + 7.0), c;
  fields.cell_vectors.push_back({"normal", normals});
  return fields;
}

// Every array of a binary file against the mesh and fields it was written from, bit for bit.
template <typename Cells>
void ExpectBinaryFileHolds(const VtuFile& file, const Vertices& vertices, const Cells& cells,
                           int vtk_type, const VtuFields& fields) {
  EXPECT_NE(file.header.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_NE(file.header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(file.header.find("NumberOfPoints=\"" + std::to_string(vertices.rows()) +
                             "\" NumberOfCells=\"" + std::to_string(cells.rows()) + "\""),
            std::string::npos);
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  ASSERT_GE(file.text.size(), tail.size());
  EXPECT_EQ(file.text.substr(file.text.size() - tail.size()), tail);
  for (const auto& [name, array] : file.arrays) {
    EXPECT_EQ(array.format, "appended") << name;
    EXPECT_TRUE(array.text_values.empty()) << name;
  }

  const VtuArray& points = file.arrays.at("Points");
  EXPECT_EQ(points.type, "Float64");
  EXPECT_EQ(points.components, 3);
  EXPECT_EQ(points.bytes, RowMajorBytes<double>(vertices));
  const VtuArray& connectivity = file.arrays.at("connectivity");
  EXPECT_EQ(connectivity.type, "Int64");
  EXPECT_EQ(connectivity.components, 1);  // a flat list of vertex ids
  EXPECT_EQ(connectivity.bytes, RowMajorBytes<std::int64_t>(cells));
  std::vector<std::int64_t> offsets;
  for (Eigen::Index c = 1; c <= cells.rows(); ++c) offsets.push_back(c * cells.cols());
  EXPECT_EQ(file.arrays.at("offsets").type, "Int64");
  EXPECT_EQ(file.arrays.at("offsets").bytes, Bytes(offsets));
  EXPECT_EQ(file.arrays.at("types").type, "UInt8");
  EXPECT_EQ(file.arrays.at("types").bytes,
            Bytes(std::vector<std::uint8_t>(cells.rows(), static_cast<std::uint8_t>(vtk_type))));

  auto expect_field = [&](const std::string& name, const auto& values, int components) {
    const std::string escaped = name == "pressure \"Pa\"" ? "pressure &quot;Pa&quot;" : name;
    ASSERT_EQ(file.arrays.count(escaped), 1u) << name;
    const VtuArray& array = file.arrays.at(escaped);
    EXPECT_EQ(array.type, "Float64") << name;
    EXPECT_EQ(array.components, components) << name;
    EXPECT_EQ(array.bytes, RowMajorBytes<double>(values)) << name;
  };
  for (const ScalarField& f : fields.point_scalars) expect_field(f.name, f.values, 1);
  for (const VectorField& f : fields.point_vectors) expect_field(f.name, f.values, 3);
  for (const ScalarField& f : fields.cell_scalars) expect_field(f.name, f.values, 1);
  for (const VectorField& f : fields.cell_vectors) expect_field(f.name, f.values, 3);
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
  WriteVtu(path, mesh, fields, VtuEncoding::kAscii);

  const VtuFile file = ReadVtu(path);
  auto values = [&](const std::string& name) { return file.arrays.at(name).text_values; };
  EXPECT_NE(file.text.find("NumberOfPoints=\"42\" NumberOfCells=\"80\""), std::string::npos);
  EXPECT_NE(file.text.find("Name=\"pressure &quot;Pa&quot;\""), std::string::npos);
  EXPECT_EQ(file.text.find("AppendedData"), std::string::npos);
  ASSERT_EQ(values("Points").size(), 3u * 42);
  EXPECT_EQ(values("Points")[3 * 7 + 1], mesh.vertices(7, 1));
  ASSERT_EQ(values("pressure &quot;Pa&quot;").size(), 42u);
  EXPECT_EQ(values("pressure &quot;Pa&quot;")[5], mesh.vertices(5, 2) * 1e3);
  EXPECT_EQ(file.arrays.at("displacement").components, 3);
  EXPECT_EQ(values("displacement")[3 * 4 + 2], mesh.vertices(4, 2) * 0.01);
  EXPECT_EQ(values("id")[79], 79.0);
  EXPECT_EQ(values("normal")[3 * 10], 1.0 / 3.0);
  ASSERT_EQ(values("connectivity").size(), 3u * 80);
  EXPECT_EQ(values("connectivity")[3 * 9 + 2], mesh.triangles(9, 2));
  EXPECT_EQ(values("offsets").back(), 240.0);
  for (double type : values("types")) EXPECT_EQ(type, 5.0);  // VTK_TRIANGLE
}

TEST(Mesh, VtuTetMeshUsesTetraCells) {
  const TetMesh mesh = MakeTetGrid({0, 0, 0}, {1, 1, 1}, {1, 1, 2});
  VtuFields fields;
  fields.cell_scalars.push_back({"E", Eigen::VectorXd::Constant(mesh.tets.rows(), 1e4)});
  const std::string path = testing::MakeScratchDir("vtu") + "/grid.vtu";
  WriteVtu(path, mesh, fields, VtuEncoding::kAscii);
  const VtuFile file = ReadVtu(path);
  auto values = [&](const std::string& name) { return file.arrays.at(name).text_values; };
  ASSERT_EQ(values("types").size(), static_cast<size_t>(mesh.tets.rows()));
  for (double type : values("types")) EXPECT_EQ(type, 10.0);  // VTK_TETRA
  EXPECT_EQ(values("offsets")[1], 8.0);
  EXPECT_EQ(values("connectivity")[4 * 3 + 1], mesh.tets(3, 1));
  EXPECT_EQ(values("E").size(), static_cast<size_t>(mesh.tets.rows()));
}

// The ASCII encoding writes exactly the text it wrote before the binary one existed.
TEST(Mesh, VtuAsciiEncodingKeepsItsTextLayout) {
  TriMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 0.5, 1.0 / 3.0;
  mesh.triangles.resize(1, 3);
  mesh.triangles << 0, 1, 2;
  VtuFields fields;
  fields.point_scalars.push_back({"p<a&b>", Eigen::Vector3d(1, 2.5, -3)});
  Eigen::Matrix<double, Eigen::Dynamic, 3> normal(1, 3);
  normal << 0, 0, 1;
  fields.cell_vectors.push_back({"n", normal});
  const std::string path = testing::MakeScratchDir("vtu") + "/triangle.vtu";
  WriteVtu(path, mesh, fields, VtuEncoding::kAscii);
  EXPECT_EQ(ReadFile(path),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n"
            "  <UnstructuredGrid>\n"
            "    <Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"
            "      <PointData Scalars=\"p&lt;a&amp;b&gt;\">\n"
            "        <DataArray type=\"Float64\" Name=\"p&lt;a&amp;b&gt;\" format=\"ascii\">\n"
            "         1\n"
            "         2.5\n"
            "         -3\n"
            "        </DataArray>\n"
            "      </PointData>\n"
            "      <CellData Vectors=\"n\">\n"
            "        <DataArray type=\"Float64\" Name=\"n\" NumberOfComponents=\"3\" "
            "format=\"ascii\">\n"
            "         0 0 1\n"
            "        </DataArray>\n"
            "      </CellData>\n"
            "      <Points>\n"
            "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
            "         0 0 0\n"
            "         1 0 0\n"
            "         0 0.5 0.3333333333333333\n"
            "        </DataArray>\n"
            "      </Points>\n"
            "      <Cells>\n"
            "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"
            "          0 1 2\n"
            "        </DataArray>\n"
            "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
            "          3\n"
            "        </DataArray>\n"
            "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"
            "          5\n"
            "        </DataArray>\n"
            "      </Cells>\n"
            "    </Piece>\n"
            "  </UnstructuredGrid>\n"
            "</VTKFile>\n");
}

TEST(Mesh, VtuBinaryIsTheDefaultAndReadsBackBitForBit) {
  const std::string dir = testing::MakeScratchDir("vtu");
  const TriMesh surface = MakeIcosphere(0.1, 2);
  const VtuFields surface_fields = SampleFields(surface.vertices, surface.triangles.rows());
  WriteVtu(dir + "/sphere.vtu", surface, surface_fields);  // the default encoding
  ExpectBinaryFileHolds(ReadVtu(dir + "/sphere.vtu"), surface.vertices, surface.triangles, 5,
                        surface_fields);

  const TetMesh grid = MakeTetGrid({-0.1, 0, 0.2}, {0.3, 0.1, 0.5}, {3, 2, 4});
  const VtuFields grid_fields = SampleFields(grid.vertices, grid.tets.rows());
  WriteVtu(dir + "/grid.vtu", grid, grid_fields, VtuEncoding::kBinary);
  const VtuFile file = ReadVtu(dir + "/grid.vtu");
  ExpectBinaryFileHolds(file, grid.vertices, grid.tets, 10, grid_fields);

  // The blocks tile the appended data in document order: each offset is the previous one
  // plus its 8-byte count and its bytes; nothing before, between or after them.
  size_t expected_offset = 0;
  size_t at = 0;
  while ((at = file.header.find("offset=\"", at)) != std::string::npos) {
    at += 8;
    EXPECT_EQ(std::stoull(file.header.substr(at)), expected_offset);
    const size_t name_at = file.header.rfind("<DataArray", at);
    const std::string tag = file.header.substr(name_at, at - name_at);
    const std::string name =
        tag.find(" Name=\"") == std::string::npos ? "Points" : Attribute(tag, "Name");
    expected_offset += 8 + file.arrays.at(name).bytes.size();
  }
  const size_t block = file.text.find('_', file.header.size()) + 1;
  EXPECT_EQ(block + expected_offset,
            file.text.size() - std::string("\n  </AppendedData>\n</VTKFile>\n").size());
}

TEST(Mesh, VtuBinaryWritesEmptyArraysOfAMeshWithoutCells) {
  TriMesh points;
  points.vertices = MakeIcosphere(1, 0).vertices;
  const std::string path = testing::MakeScratchDir("vtu") + "/points.vtu";
  WriteVtu(path, points, {}, VtuEncoding::kBinary);
  const VtuFile file = ReadVtu(path);
  EXPECT_EQ(file.arrays.at("Points").bytes, RowMajorBytes<double>(points.vertices));
  EXPECT_TRUE(file.arrays.at("connectivity").bytes.empty());
  EXPECT_TRUE(file.arrays.at("offsets").bytes.empty());
  EXPECT_TRUE(file.arrays.at("types").bytes.empty());
}

TEST(Mesh, VtuBinaryIsSmallerThanAscii) {
  const TetMesh grid = MakeTetGrid({0, 0, 0}, {0.3, 0.2, 0.1}, {6, 4, 2});
  VtuFields fields;
  fields.point_vectors.push_back({"displacement", grid.vertices * (1.0 / 3.0)});
  const std::string dir = testing::MakeScratchDir("vtu");
  WriteVtu(dir + "/binary.vtu", grid, fields, VtuEncoding::kBinary);
  WriteVtu(dir + "/ascii.vtu", grid, fields, VtuEncoding::kAscii);
  EXPECT_LT(ReadFile(dir + "/binary.vtu").size(), ReadFile(dir + "/ascii.vtu").size());
}

TEST(Mesh, VtuEncodingNamesParseBack) {
  for (VtuEncoding encoding : {VtuEncoding::kBinary, VtuEncoding::kAscii}) {
    VtuEncoding parsed =
        encoding == VtuEncoding::kBinary ? VtuEncoding::kAscii : VtuEncoding::kBinary;
    EXPECT_TRUE(ParseVtuEncoding(VtuEncodingName(encoding), &parsed));
    EXPECT_EQ(parsed, encoding);
  }
  VtuEncoding untouched = VtuEncoding::kAscii;
  for (const char* word : {"", "Binary", "raw", "base64", "ascii "})
    EXPECT_FALSE(ParseVtuEncoding(word, &untouched)) << word;
  EXPECT_EQ(untouched, VtuEncoding::kAscii);
}

TEST(Mesh, VtuFieldOfTheWrongSizeIsAProgrammingError) {
  const TriMesh mesh = MakeIcosphere(0.1, 0);
  VtuFields fields;
  fields.point_scalars.push_back({"short", Eigen::VectorXd::Zero(3)});
  const std::string path = testing::MakeScratchDir("vtu") + "/bad.vtu";
  EXPECT_DEATH(WriteVtu(path, mesh, fields), "wrong number of rows");
}

// ---- meshio (tests/mesh/read_vtu_with_meshio.py) ----

struct MeshioArray {
  std::string dtype;
  std::vector<std::vector<std::string>> rows;  // the printed values, row by row
};

// "KIND NAME" → array, from the script's output.
std::map<std::string, MeshioArray> ReadMeshioDump(const std::string& text) {
  std::map<std::string, MeshioArray> arrays;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    // KIND NAME... DTYPE ROWS COLUMNS (the name may hold spaces).
    std::vector<std::string> words;
    std::istringstream split(line);
    for (std::string word; split >> word;) words.push_back(word);
    if (words.size() < 5) {
      ADD_FAILURE() << "unexpected line from meshio: " << line;
      break;
    }
    const size_t kind_end = line.find(' ');
    const size_t name_end = line.rfind(' ', line.rfind(' ', line.rfind(' ') - 1) - 1);
    MeshioArray& array =
        arrays[words[0] + " " + line.substr(kind_end + 1, name_end - kind_end - 1)];
    array.dtype = words[words.size() - 3];
    const int rows = std::stoi(words[words.size() - 2]);
    for (int r = 0; r < rows && std::getline(in, line); ++r) {
      std::vector<std::string> values;
      std::istringstream row(line);
      for (std::string value; row >> value;) values.push_back(value);
      array.rows.push_back(values);
    }
  }
  return arrays;
}

// meshio's array against `values` exactly: floats printed by repr() parse back to the very
// doubles written.
template <typename Matrix>
void ExpectMeshioHolds(const std::map<std::string, MeshioArray>& arrays, const std::string& key,
                       const std::string& dtype, const Matrix& values) {
  ASSERT_EQ(arrays.count(key), 1u) << key << " missing from meshio's reading";
  const MeshioArray& array = arrays.at(key);
  EXPECT_EQ(array.dtype, dtype) << key;
  ASSERT_EQ(array.rows.size(), static_cast<size_t>(values.rows())) << key;
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    ASSERT_EQ(array.rows[i].size(), static_cast<size_t>(values.cols())) << key << " row " << i;
    for (Eigen::Index k = 0; k < values.cols(); ++k) {
      const double read = std::strtod(array.rows[i][k].c_str(), nullptr);
      const double written = static_cast<double>(values(i, k));
      EXPECT_EQ(std::memcmp(&read, &written, sizeof read), 0)
          << key << "(" << i << ", " << k << "): meshio read " << array.rows[i][k] << ", written "
          << written;
    }
  }
}

template <typename Cells>
void ExpectMeshioReads(const std::string& path, const Vertices& vertices, const Cells& cells,
                       const std::string& cell_type, const VtuFields& fields) {
  const std::string dump = path + ".meshio.txt";
  ChildOptions options;
  options.output = dump;
  const ChildProcessResult run = RunChildProcess(
      {kSystemPython, testing::SourcePath("tests/mesh/read_vtu_with_meshio.py"), path}, options);
  ASSERT_TRUE(run.ok()) << run.Describe() << "\n" << ReadFile(dump);
  const std::map<std::string, MeshioArray> arrays = ReadMeshioDump(ReadFile(dump));
  EXPECT_EQ(arrays.size(), 6u);  // points, one cell block, four fields
  ExpectMeshioHolds(arrays, "points -", "float64", vertices);
  ExpectMeshioHolds(arrays, "cells " + cell_type, "int64", cells);
  for (const ScalarField& f : fields.point_scalars)
    ExpectMeshioHolds(arrays, "point_data " + f.name, "float64", f.values);
  for (const VectorField& f : fields.point_vectors)
    ExpectMeshioHolds(arrays, "point_data " + f.name, "float64", f.values);
  for (const ScalarField& f : fields.cell_scalars)
    ExpectMeshioHolds(arrays, "cell_data " + f.name, "float64", f.values);
  for (const VectorField& f : fields.cell_vectors)
    ExpectMeshioHolds(arrays, "cell_data " + f.name, "float64", f.values);
}

TEST(Mesh, VtuBinaryFileReadsBackInMeshio) {
  if (!RunChildProcess({kSystemPython, "-c", "import meshio"}, /*quiet=*/true).ok()) {
    GTEST_SKIP() << kSystemPython
                 << " cannot import meshio (Debian: apt-get install python3-meshio)";
  }
  const std::string dir = testing::MakeScratchDir("vtu_meshio");
  const TriMesh surface = MakeIcosphere(0.1, 1);
  const VtuFields surface_fields = SampleFields(surface.vertices, surface.triangles.rows());
  WriteVtu(dir + "/sphere.vtu", surface, surface_fields);
  ExpectMeshioReads(dir + "/sphere.vtu", surface.vertices, surface.triangles, "triangle",
                    surface_fields);

  const TetMesh grid = MakeTetGrid({-0.1, 0, 0.2}, {0.3, 0.1, 0.5}, {2, 2, 3});
  const VtuFields grid_fields = SampleFields(grid.vertices, grid.tets.rows());
  WriteVtu(dir + "/grid.vtu", grid, grid_fields);
  ExpectMeshioReads(dir + "/grid.vtu", grid.vertices, grid.tets, "tetra", grid_fields);
}

}  // namespace
}  // namespace ergo
