#include "ergo/mesh/stl_format.h"

#include <cstring>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/binary_reader.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kTriangleBytes = 50;

// Welds corners with identical coordinates (by value: -0 and +0 are the same point).
class CornerWelder {
 public:
  explicit CornerWelder(SurfaceBuilder* builder) : builder_(builder) {}
  int Add(double x, double y, double z, int line) {
    const Point point{x + 0.0, y + 0.0, z + 0.0};  // + 0.0 turns -0 into +0
    const auto [it, inserted] = index_.emplace(point, static_cast<int>(builder_->vertex_count()));
    if (inserted) builder_->AddVertex(x, y, z, line);
    return it->second;
  }
  void Reserve(size_t corners) { index_.reserve(corners / 4); }

 private:
  struct Point {
    double x, y, z;
    bool operator==(const Point& other) const {
      return x == other.x && y == other.y && z == other.z;
    }
  };
  struct PointHash {
    size_t operator()(const Point& p) const {
      uint64_t bits[3];
      std::memcpy(&bits[0], &p.x, 8);
      std::memcpy(&bits[1], &p.y, 8);
      std::memcpy(&bits[2], &p.z, 8);
      uint64_t h = bits[0] * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ bits[1]) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 32) ^ bits[2]) * 0x94D049BB133111EBull;
      return static_cast<size_t>(h ^ (h >> 31));
    }
  };
  SurfaceBuilder* builder_;
  std::unordered_map<Point, int, PointHash> index_;
};

bool StartsWithSolid(std::string_view bytes) {
  size_t i = 0;
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  while (i < bytes.size() &&
         (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) {
    ++i;
  }
  return ToLower(bytes.substr(i, 5)) == "solid";
}

void ReadBinary(const std::string& path, const std::string& bytes, uint64_t triangle_count,
                SurfaceBuilder* builder) {
  ByteReader reader(bytes, kHeaderBytes + 4, ByteOrder::kLittleEndian);
  CornerWelder welder(builder);
  welder.Reserve(3 * triangle_count);
  builder->Reserve(static_cast<int64_t>(triangle_count / 2 + 3),
                   static_cast<int64_t>(triangle_count));
  for (uint64_t t = 0; t < triangle_count; ++t) {
    reader.Skip(12);  // the facet normal: recomputed from the corners when needed
    int corners[3];
    for (int k = 0; k < 3; ++k) {
      float xyz[3] = {0, 0, 0};
      for (float& value : xyz) reader.ReadFloat32(&value);
      RequireFinite(path, "triangle " + std::to_string(t), 3 * t + k, xyz[0], xyz[1], xyz[2]);
      corners[k] = welder.Add(xyz[0], xyz[1], xyz[2], 0);
    }
    reader.Skip(2);  // attribute byte count
    builder->AddPolygon(corners, 3, 0, "triangle " + std::to_string(t));
  }
}

void ReadAscii(const std::string& path, const std::string& bytes, SurfaceBuilder* builder,
               ReadDetails* details) {
  const std::string text = BytesToText(bytes);
  TextReader reader(path, text);
  TokenStream stream(&reader, '\0');
  CornerWelder welder(builder);
  std::vector<int> loop;
  bool in_loop = false, in_solid = false, saw_solid = false;
  int loop_line = 0;
  int64_t corner_count = 0;
  std::string_view token;
  while (stream.Next(&token)) {
    const std::string word = ToLower(token);
    if (word == "solid") {
      in_solid = saw_solid = true;
      stream.SkipRestOfLine();  // the solid's name
    } else if (word == "endsolid") {
      in_solid = false;
      stream.SkipRestOfLine();
    } else if (word == "facet") {
      stream.SkipRestOfLine();  // "normal nx ny nz": recomputed from the corners when needed
    } else if (word == "outer") {
      if (!stream.Next(&token) || ToLower(token) != "loop") {
        reader.Fail("'outer' is not followed by 'loop'", "check the file; it may be damaged");
      }
      in_loop = true;
      loop.clear();
      loop_line = reader.line_number();
    } else if (word == "vertex") {
      if (!in_loop) {
        reader.Fail("'vertex' outside an 'outer loop' ... 'endloop' block",
                    "check the file; it may be damaged");
      }
      double xyz[3];
      for (double& value : xyz) {
        if (!stream.Next(&token)) {
          reader.Fail("the file ends inside a vertex", "the file is truncated: re-export it");
        }
        value = ParseCoordinate(reader, token, corner_count);
      }
      ++corner_count;
      loop.push_back(welder.Add(xyz[0], xyz[1], xyz[2], reader.line_number()));
    } else if (word == "endloop") {
      if (!in_loop) reader.Fail("'endloop' without 'outer loop'", "check the file");
      in_loop = false;
      builder->AddPolygon(loop.data(), static_cast<int>(loop.size()), loop_line,
                          "line " + std::to_string(loop_line));
    } else if (word == "endfacet") {
      // Nothing to do: the facet's loop was closed by endloop.
    } else {
      reader.Fail("unexpected word " + Quote(token) + " in an ASCII STL file",
                  "check that the file is ASCII STL (solid / facet / outer loop / vertex / "
                  "endloop / endfacet / endsolid)");
    }
  }
  if (in_loop) {
    reader.Fail("the file ends inside a facet", "the file is truncated: re-export it");
  }
  if (saw_solid && in_solid) {
    AddNote(details, true, "", "the file ends without 'endsolid': it may be truncated",
            "re-export the mesh");
  }
}

Eigen::Vector3d UnitNormal(const TriMesh& mesh, Eigen::Index f) {
  const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0));
  const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1));
  const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

}  // namespace

TriMesh ReadStl(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  const std::string bytes = ReadFileBytes(path);
  SurfaceBuilder builder;
  const bool solid = StartsWithSolid(bytes);
  uint64_t declared = 0;
  uint64_t binary_size = 0;
  if (bytes.size() >= kHeaderBytes + 4) {
    ByteReader(bytes, kHeaderBytes, ByteOrder::kLittleEndian).ReadUnsigned(4, &declared);
    binary_size = kHeaderBytes + 4 + kTriangleBytes * declared;
  }
  std::string format;
  if (binary_size == bytes.size()) {
    format = "STL binary";
    ReadBinary(path, bytes, declared, &builder);
  } else if (solid) {
    format = "STL ASCII";
    try {
      ReadAscii(path, bytes, &builder, details);
    } catch (const InputError& error) {
      // Text that fails as ASCII STL is just broken; binary bytes mean a damaged binary STL.
      if (bytes.size() < kHeaderBytes + 4 || bytes.find('\0') == std::string::npos) throw;
      // A binary file whose header starts with "solid" but whose size is off.
      throw InputError(path, error.location(),
                       error.problem() + "; read as binary instead, its header declares " +
                           std::to_string(declared) + " triangles, i.e. " +
                           std::to_string(binary_size) + " bytes, but the file has " +
                           std::to_string(bytes.size()),
                       "the file is damaged or truncated: re-export it");
    }
  } else if (bytes.size() < kHeaderBytes + 4) {
    throw InputError(path, "",
                     "the file has " + std::to_string(bytes.size()) +
                         " bytes: too short for a binary STL (at least 84) and not ASCII STL "
                         "(which starts with 'solid')",
                     "the file is truncated or not STL: re-export it");
  } else if (binary_size < bytes.size()) {
    format = "STL binary";
    AddNote(details, true, "",
            std::to_string(bytes.size() - binary_size) + " bytes after the " +
                std::to_string(declared) + " declared triangles were ignored",
            "check the exporter; a binary STL is exactly 84 + 50 bytes per triangle");
    ReadBinary(path, bytes, declared, &builder);
  } else {
    throw InputError(path, "",
                     "binary STL header declares " + std::to_string(declared) +
                         " triangles, which need " + std::to_string(binary_size) +
                         " bytes, but the file has " + std::to_string(bytes.size()) +
                         ": the file is truncated or not STL",
                     "re-export the mesh");
  }
  return builder.Finish(path, options, format, details);
}

void WriteStl(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  const std::string unit = options.unit == LengthUnit::kMillimetre ? "mm" : "m";
  if (options.encoding == Encoding::kBinary) {
    WriteFileAtomically(path, [&](std::ostream& out) {
      std::string header = "ergo binary STL, unit " + unit;
      header.resize(kHeaderBytes, ' ');  // must not start with "solid"
      out.write(header.data(), kHeaderBytes);
      WriteLittleEndian(out, static_cast<uint64_t>(mesh.triangles.rows()), 4);
      for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
        const Eigen::Vector3d normal = UnitNormal(mesh, f);
        for (int k = 0; k < 3; ++k) WriteFloat32LE(out, static_cast<float>(normal(k)));
        for (int c = 0; c < 3; ++c) {
          for (int k = 0; k < 3; ++k) {
            WriteFloat32LE(
                out, static_cast<float>(mesh.vertices(mesh.triangles(f, c), k) / metres_per_unit));
          }
        }
        WriteLittleEndian(out, 0, 2);
      }
    });
    return;
  }
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "solid ergo_unit_" << unit << "\n";
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      const Eigen::Vector3d normal = UnitNormal(mesh, f);
      out << " facet normal ";
      for (int k = 0; k < 3; ++k) {
        if (k > 0) out << ' ';
        WriteDouble(out, normal(k));
      }
      out << "\n  outer loop\n";
      for (int c = 0; c < 3; ++c) {
        out << "   vertex";
        for (int k = 0; k < 3; ++k) {
          out << ' ';
          WriteDouble(out, mesh.vertices(mesh.triangles(f, c), k) / metres_per_unit);
        }
        out << '\n';
      }
      out << "  endloop\n endfacet\n";
    }
    out << "endsolid ergo_unit_" << unit << "\n";
  });
}

}  // namespace ergo
