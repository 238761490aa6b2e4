#include "ergo/mesh/tetgen_format.h"

#include <filesystem>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

const char kTriangleFix[] =
    "this is a 2-D file of the Triangle program; ergo needs a 3-D TetGen mesh (tetgen -p "
    "surface.stl makes one)";

std::string WithExtension(const std::string& path, const std::string& extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

std::vector<int64_t> ReadHeaderNumbers(TextReader& reader, size_t min_count, const char* what) {
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('#', &tokens)) {
    reader.Fail("the file has no header line", std::string("start it with ") + what);
  }
  if (tokens.size() < min_count) {
    reader.Fail("the header line should be " + std::string(what),
                "the file is damaged: re-export it");
  }
  std::vector<int64_t> numbers;
  for (size_t k = 0; k < tokens.size() && k < 4; ++k) {
    numbers.push_back(ParseInteger(reader, tokens[k], "header value"));
  }
  return numbers;
}

// Reads the .node file; returns coordinates (file units), line per node and the first number.
int64_t ReadNodes(const std::string& path, std::vector<double>* xyz, std::vector<int>* lines) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  const std::vector<int64_t> header =
      ReadHeaderNumbers(reader, 2, "'points dimension attributes boundary-markers'");
  const int64_t count = header[0], dim = header[1];
  if (dim == 2) reader.Fail("the file has dimension 2, not 3", kTriangleFix);
  if (dim != 3) {
    reader.Fail("the file has dimension " + std::to_string(dim) + "; TetGen files have 3",
                "check the file; it may be damaged");
  }
  RequireCountFits(path, reader.Location(), "nodes", count, 8, reader.remaining_bytes());
  xyz->reserve(static_cast<size_t>(3 * count));
  lines->reserve(static_cast<size_t>(count));
  int64_t first = 0;
  std::vector<std::string_view> tokens;
  for (int64_t n = 0; n < count; ++n) {
    if (!reader.NextTokens('#', &tokens)) {
      reader.Fail("the file ends after " + std::to_string(n) + " of the " + std::to_string(count) +
                      " nodes the header declares",
                  "the file is truncated or its count is wrong: re-export it");
    }
    if (tokens.size() < 4) {
      reader.Fail("a node line must be 'number x y z [attributes] [marker]', found " +
                      std::to_string(tokens.size()) + " values",
                  "the file is damaged: re-export it");
    }
    const int64_t number = ParseInteger(reader, tokens[0], "node number");
    if (n == 0) {
      if (number != 0 && number != 1) {
        reader.Fail("the first node is numbered " + std::to_string(number) + ", not 0 or 1",
                    "number the nodes from 0 or 1 consecutively");
      }
      first = number;
    } else if (number != first + n) {
      reader.Fail("node number " + std::to_string(number) + " breaks the sequence (expected " +
                      std::to_string(first + n) + ")",
                  "number the nodes from 0 or 1 consecutively");
    }
    for (int k = 1; k <= 3; ++k) xyz->push_back(ParseCoordinate(reader, tokens[k], number));
    lines->push_back(reader.line_number());
  }
  return first;
}

}  // namespace

std::string TetGenNodePath(const std::string& path) { return WithExtension(path, ".node"); }
std::string TetGenElePath(const std::string& path) { return WithExtension(path, ".ele"); }

TetMesh ReadTetGen(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  const std::string node_path = TetGenNodePath(path);
  const std::string ele_path = TetGenElePath(path);
  std::vector<double> xyz;
  std::vector<int> vertex_lines;
  const int64_t first = ReadNodes(node_path, &xyz, &vertex_lines);
  const int64_t vertex_count = static_cast<int64_t>(xyz.size() / 3);

  const std::string node_name = std::filesystem::path(node_path).filename().string();
  const std::string text = BytesToText(ReadFileBytes(ele_path));
  TextReader reader(ele_path, text);
  const std::vector<int64_t> header =
      ReadHeaderNumbers(reader, 2, "'tetrahedra nodes-per-tet attributes'");
  const int64_t count = header[0], per_tet = header[1];
  if (per_tet == 3) reader.Fail("elements have 3 nodes (triangles), not 4", kTriangleFix);
  if (per_tet != 4 && per_tet != 10) {
    reader.Fail("elements have " + std::to_string(per_tet) + " nodes; TetGen tets have 4 or 10",
                "check the file; it may be damaged");
  }
  RequireCountFits(ele_path, reader.Location(), "tetrahedra", count, 10, reader.remaining_bytes());
  std::vector<int> tets;
  std::vector<int> tet_lines;
  tets.reserve(static_cast<size_t>(4 * count));
  std::vector<std::string_view> tokens;
  for (int64_t t = 0; t < count; ++t) {
    if (!reader.NextTokens('#', &tokens)) {
      reader.Fail("the file ends after " + std::to_string(t) + " of the " + std::to_string(count) +
                      " tetrahedra the header declares",
                  "the file is truncated or its count is wrong: re-export it");
    }
    if (static_cast<int64_t>(tokens.size()) < 1 + per_tet) {
      reader.Fail("a tetrahedron line needs its number and " + std::to_string(per_tet) +
                      " node numbers, found " + std::to_string(tokens.size()) + " values",
                  "the file is damaged: re-export it");
    }
    for (int k = 1; k <= 4; ++k) {
      const int64_t number = ParseInteger(reader, tokens[k], "node number");
      if (number - first < 0 || number - first >= vertex_count) {
        // The tetrahedron's own number as written (quoted and cut when it is no short word).
        const std::string name = tokens[0].size() <= 20 ? std::string(tokens[0]) : Quote(tokens[0]);
        reader.Fail("tetrahedron " + name + " refers to node " + std::to_string(number) + ", but " +
                        node_name + " has " + std::to_string(vertex_count) +
                        " nodes, numbered from " + std::to_string(first),
                    "re-export the mesh; every tetrahedron must name nodes of its .node file");
      }
      tets.push_back(static_cast<int>(number - first));
    }
    tet_lines.push_back(reader.line_number());
  }
  if (count == 0) {
    throw InputError(ele_path, "", "the file declares no tetrahedra",
                     "tetrahedralise the volume (e.g. tetgen -p surface.stl) and save again");
  }
  TetMesh mesh;
  mesh.vertices = Eigen::Map<const Vertices>(xyz.data(), vertex_count, 3);
  mesh.tets = Eigen::Map<const Tetrahedra>(tets.data(), count, 4);
  ScaleToMetres(options, &mesh.vertices);
  if (details) {
    details->format = "TetGen .node/.ele (" + std::to_string(first) + "-based)";
    details->vertex_lines = std::move(vertex_lines);
    details->element_lines = std::move(tet_lines);
    details->vertex_file = node_path;
    details->element_file = ele_path;
    if (per_tet == 10) {
      AddNote(details, false, "",
              "10-node tetrahedra: only their corner nodes are used (ergo's elements are "
              "linear)");
    }
  }
  return mesh;
}

void WriteTetGen(const std::string& path, const TetMesh& mesh, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  WriteFileAtomically(TetGenNodePath(path), [&](std::ostream& out) {
    out << mesh.vertices.rows() << "  3  0  0\n";
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      out << v + 1;
      for (int k = 0; k < 3; ++k) {
        out << "  ";
        WriteDouble(out, mesh.vertices(v, k) / metres_per_unit);
      }
      out << '\n';
    }
    out << "# ergo tetrahedral mesh, unit "
        << (options.unit == LengthUnit::kMillimetre ? "mm" : "m") << "\n";
  });
  WriteFileAtomically(TetGenElePath(path), [&](std::ostream& out) {
    out << mesh.tets.rows() << "  4  0\n";
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
      out << t + 1;
      for (int k = 0; k < 4; ++k) out << "  " << mesh.tets(t, k) + 1;
      out << '\n';
    }
    out << "# ergo tetrahedral mesh\n";
  });
}

}  // namespace ergo
