#include "ergo/mesh/msh_format.h"

#include <cmath>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/binary_reader.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/msh_elements.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

const char kConvert[] =
    "convert it with gmsh: gmsh FILE -0 -format msh41 -o OUT.msh (or -format msh22)";

struct MshVersionInfo {
  int major = 0;
  bool v41 = false;
  bool binary = false;
  ByteOrder order = ByteOrder::kLittleEndian;
  std::string name;
};

// Reads $MeshFormat ... $EndMeshFormat (the first line has been read into `first`).
MshVersionInfo ReadFormat(TextReader& reader, const std::vector<std::string_view>& first) {
  if (first[0] == "$NOD" || first[0] == "$NOE") {
    reader.Fail("this is a gmsh MSH 1 file, which ergo does not read", kConvert);
  }
  if (first[0] != "$MeshFormat") {
    reader.Fail(
        "not a gmsh .msh file: it starts with " + Quote(first[0]) + " instead of $MeshFormat",
        "check the file's format");
  }
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('\0', &tokens) || tokens.size() < 3) {
    reader.Fail("the $MeshFormat section needs 'version file-type data-size'",
                "the file is damaged: re-export it");
  }
  double version = 0;
  int64_t file_type = 0, data_size = 0;
  if (!ParseDouble(tokens[0], &version) || !ParseInt64(tokens[1], &file_type) ||
      !ParseInt64(tokens[2], &data_size) || !(version > 0 && version < 100)) {
    reader.Fail("cannot read the $MeshFormat line " + Quote(tokens[0]),
                "the file is damaged: re-export it");
  }
  MshVersionInfo info;
  info.major = static_cast<int>(std::floor(version));
  info.binary = file_type != 0;
  const std::string shown(tokens[0]);
  if (info.major == 3) {
    reader.Fail("this is a gmsh MSH " + shown + " file, which ergo does not read", kConvert);
  }
  if (info.major != 2 && info.major != 4) {
    reader.Fail("unknown gmsh MSH version " + shown, kConvert);
  }
  info.v41 = info.major == 4 && version > 4.05;
  if (info.major == 4 && version != 4.0 && version != 4.1) {
    reader.Fail("unknown gmsh MSH version " + shown, kConvert);
  }
  if (info.binary && info.major == 4) {
    reader.Fail("binary gmsh MSH 4 files are not read by ergo",
                "save it as ASCII: gmsh FILE -0 -format msh41 -o OUT.msh (without -bin)");
  }
  if (info.binary && data_size != 8) {
    reader.Fail("binary gmsh file with " + std::to_string(data_size) + "-byte reals",
                "save it as ASCII: gmsh FILE -0 -format msh22 -o OUT.msh");
  }
  if (info.binary) {
    // A binary file writes the integer 1 here so readers can tell its byte order.
    ByteReader one(reader.text(), reader.offset(), ByteOrder::kLittleEndian);
    uint64_t value = 0;
    if (!one.ReadUnsigned(4, &value) || (value != 1 && value != 0x01000000)) {
      reader.Fail("the binary $MeshFormat section lacks the byte-order mark (integer 1)",
                  "the file is damaged: re-export it");
    }
    info.order = value == 1 ? ByteOrder::kLittleEndian : ByteOrder::kBigEndian;
    reader.Seek(one.offset());
  }
  msh::ExpectSectionEnd(reader, "$EndMeshFormat", "the format section is damaged");
  info.name = "gmsh " + shown + (info.binary ? " binary" : " ASCII");
  return info;
}

// Skips a section this reader does not use, up to and including its $End line.
void SkipSection(TextReader& reader, const std::string& name) {
  const std::string end = "$End" + name;
  const std::string_view text = reader.text();
  size_t at = reader.offset();
  while (true) {
    at = text.find(end, at);
    if (at == std::string_view::npos) {
      reader.Fail("section $" + name + " has no " + end + ": the file is truncated",
                  "re-export the mesh");
    }
    // Binary sections run straight into their end tag, so only what follows is checked.
    const size_t after = at + end.size();
    if (after == text.size() || text[after] == '\n' || text[after] == '\r' || text[after] == ' ') {
      break;
    }
    at = after;
  }
  reader.SkipTo(at);
  std::string_view line;
  reader.NextLine(&line);
}

Eigen::Vector3d Lowest(const Vertices& v) {
  return v.rows() > 0 ? Eigen::Vector3d(v.colwise().minCoeff()) : Eigen::Vector3d::Zero();
}
Eigen::Vector3d Highest(const Vertices& v) {
  return v.rows() > 0 ? Eigen::Vector3d(v.colwise().maxCoeff()) : Eigen::Vector3d::Zero();
}

// Writes nodes and elements of `corners` columns as gmsh type `type` in one entity.
template <typename Elements>
void WriteMshBody(std::ostream& out, const Vertices& vertices, const Elements& elements, int type,
                  int dim, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  const Eigen::Index nv = vertices.rows(), ne = elements.rows();
  const int corners = static_cast<int>(elements.cols());
  auto write_point = [&](Eigen::Index v) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out << ' ';
      WriteDouble(out, vertices(v, k) / metres_per_unit);
    }
    out << '\n';
  };
  if (options.msh_version == MshVersion::k22) {
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << nv << '\n';
    for (Eigen::Index v = 0; v < nv; ++v) {
      out << v + 1 << ' ';
      write_point(v);
    }
    out << "$EndNodes\n$Elements\n" << ne << '\n';
    for (Eigen::Index e = 0; e < ne; ++e) {
      out << e + 1 << ' ' << type << " 2 1 1";  // tags: physical group 1, entity 1
      for (int k = 0; k < corners; ++k) out << ' ' << elements(e, k) + 1;
      out << '\n';
    }
    out << "$EndElements\n";
    return;
  }
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n"
      << (dim == 2 ? "0 0 1 0\n" : "0 0 0 1\n") << "1";
  const Eigen::Vector3d lo = Lowest(vertices) / metres_per_unit;
  const Eigen::Vector3d hi = Highest(vertices) / metres_per_unit;
  for (int k = 0; k < 3; ++k) {
    out << ' ';
    WriteDouble(out, lo(k));
  }
  for (int k = 0; k < 3; ++k) {
    out << ' ';
    WriteDouble(out, hi(k));
  }
  out << " 0 0\n$EndEntities\n";
  out << "$Nodes\n1 " << nv << " 1 " << nv << '\n' << dim << " 1 0 " << nv << '\n';
  for (Eigen::Index v = 0; v < nv; ++v) out << v + 1 << '\n';
  for (Eigen::Index v = 0; v < nv; ++v) write_point(v);
  out << "$EndNodes\n$Elements\n1 " << ne << " 1 " << ne << '\n'
      << dim << " 1 " << type << ' ' << ne << '\n';
  for (Eigen::Index e = 0; e < ne; ++e) {
    out << e + 1;
    for (int k = 0; k < corners; ++k) out << ' ' << elements(e, k) + 1;
    out << '\n';
  }
  out << "$EndElements\n";
}

}  // namespace

AnyMesh ReadMsh(const std::string& path, const ReadOptions& options, MshContent content,
                ReadDetails* details) {
  const std::string bytes = ReadFileBytes(path);
  TextReader reader(path, bytes);
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('\0', &tokens)) {
    reader.Fail("the file has only blank lines", "re-export the mesh");
  }
  const MshVersionInfo version = ReadFormat(reader, tokens);
  msh::Collector collector(path);
  bool have_nodes = false, have_elements = false;
  while (reader.NextTokens('\0', &tokens)) {
    const std::string_view section = tokens[0];
    if (section.size() < 2 || section[0] != '$' || tokens.size() != 1) {
      reader.Fail("expected a section such as $Nodes, found " + Quote(section),
                  "the file is damaged or its counts are wrong: re-export it");
    }
    const std::string name(section.substr(1));
    if (name == "Nodes" || name == "Elements") {
      const bool nodes = name == "Nodes";
      if ((nodes && have_nodes) || (!nodes && have_elements)) {
        reader.Fail("a second $" + name + " section", "re-export the mesh as one piece");
      }
      if (!nodes && !have_nodes) {
        reader.Fail("$Elements comes before $Nodes", "re-export the mesh with gmsh");
      }
      if (nodes) {
        have_nodes = true;
        if (version.binary) {
          msh::ReadNodesV2Binary(reader, version.order, &collector);
        } else if (version.major == 2) {
          msh::ReadNodesV2(reader, &collector);
        } else {
          msh::ReadNodesV4(reader, version.v41, &collector);
        }
      } else {
        have_elements = true;
        if (version.binary) {
          msh::ReadElementsV2Binary(reader, version.order, &collector);
        } else if (version.major == 2) {
          msh::ReadElementsV2(reader, &collector);
        } else {
          msh::ReadElementsV4(reader, version.v41, &collector);
        }
      }
    } else {
      SkipSection(reader, name);
    }
  }
  if (!have_elements) {
    throw InputError(path, "", "the file has no $Elements section (" + version.name + ")",
                     "mesh the geometry in gmsh before saving");
  }
  return collector.Finish(options, content, version.name, details);
}

void WriteMsh(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    WriteMshBody(out, mesh.vertices, mesh.triangles, 2, 2, options);
  });
}

void WriteMsh(const std::string& path, const TetMesh& mesh, const WriteOptions& options) {
  WriteFileAtomically(
      path, [&](std::ostream& out) { WriteMshBody(out, mesh.vertices, mesh.tets, 4, 3, options); });
}

}  // namespace ergo
