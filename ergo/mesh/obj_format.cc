#include "ergo/mesh/obj_format.h"

#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

// A face that names a vertex defined later in the file: legal in practice, checked at the end.
struct ForwardReference {
  int line;
  int64_t index;  // 1-based, as written
};

bool EndsWithBackslash(std::string_view line) {
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  return !line.empty() && line.back() == '\\';
}

// Parses the vertex index of a face corner "i", "i/t", "i//n" or "i/t/n" to 0-based.
int64_t CornerIndex(const TextReader& reader, std::string_view token, int64_t vertices_so_far,
                    std::vector<ForwardReference>* forward) {
  const std::string_view index_text = token.substr(0, token.find('/'));
  int64_t index = 0;
  if (index_text.empty() || !ParseInt64(index_text, &index)) {
    reader.Fail("face corner " + Quote(token) + " does not start with a vertex index",
                "write face corners as v, v/vt, v//vn or v/vt/vn with integer v");
  }
  if (index == 0) {
    reader.Fail("face refers to vertex 0, but OBJ vertex numbers start at 1",
                "re-export the mesh; OBJ indices are 1-based (negative ones count back)");
  }
  if (index < 0) {
    if (-index > vertices_so_far) {
      reader.Fail("face refers to vertex " + std::to_string(index) + " (relative), but only " +
                      std::to_string(vertices_so_far) + " vertices precede it",
                  "re-export the mesh; every face index must name an existing vertex");
    }
    return vertices_so_far + index;
  }
  if (index > std::numeric_limits<int>::max()) {
    reader.Fail("face refers to vertex " + std::to_string(index) + ", beyond any mesh",
                "re-export the mesh; every face index must name an existing vertex");
  }
  if (index > vertices_so_far) forward->push_back({reader.line_number(), index});
  return index - 1;
}

}  // namespace

TriMesh ReadObj(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  bool was_utf16 = false;
  const std::string text = BytesToText(ReadFileBytes(path), &was_utf16);
  TextReader reader(path, text);
  SurfaceBuilder builder;
  std::vector<ForwardReference> forward;
  std::vector<int> corners;
  std::string joined;  // a record continued over lines ending in '\'
  int64_t lines_and_points = 0;
  std::string_view line;
  while (reader.NextLine(&line)) {
    const int record_line = reader.line_number();
    if (EndsWithBackslash(line)) {
      joined.assign(line);
      while (EndsWithBackslash(joined)) {
        joined.erase(joined.rfind('\\'));
        std::string_view next;
        if (!reader.NextLine(&next)) break;
        joined.push_back(' ');
        joined.append(next);
      }
      line = joined;
    }
    LineTokens tokens(line, '#');
    std::string_view keyword;
    if (!tokens.Next(&keyword)) continue;
    if (keyword == "f") {
      // Faces are polygons of any size: read token by token, at any line length.
      corners.clear();
      std::string_view corner;
      while (tokens.Next(&corner)) {
        corners.push_back(
            static_cast<int>(CornerIndex(reader, corner, builder.vertex_count(), &forward)));
      }
      if (corners.empty()) {
        reader.Fail("face record has no vertex indices",
                    "remove the empty 'f' line or list the face's vertices");
      }
      builder.AddPolygon(corners.data(), static_cast<int>(corners.size()), record_line,
                         "line " + std::to_string(record_line));
    } else if (keyword == "l" || keyword == "p") {
      ++lines_and_points;
    } else if (keyword == "v") {
      reader.RequireRecordLength(line);
      const int64_t vertex = builder.vertex_count();
      std::string_view xyz[3];
      int found = 0;
      while (found < 3 && tokens.Next(&xyz[found])) ++found;
      if (found < 3) {
        reader.Fail("vertex " + std::to_string(vertex + 1) + " has " + std::to_string(found) +
                        " coordinates instead of 3",
                    "write vertices as 'v x y z'");
      }
      // Messages use OBJ's 1-based vertex numbers.
      const double x = ParseCoordinate(reader, xyz[0], vertex + 1);
      const double y = ParseCoordinate(reader, xyz[1], vertex + 1);
      const double z = ParseCoordinate(reader, xyz[2], vertex + 1);
      builder.AddVertex(x, y, z, record_line);
    }
  }
  for (const ForwardReference& reference : forward) {
    RequireVertexIndex(path, "line " + std::to_string(reference.line), "face", reference.index - 1,
                       reference.index, builder.vertex_count());
  }
  if (was_utf16) AddNote(details, false, "", "the file is UTF-16 text; it was decoded");
  if (lines_and_points > 0) {
    AddNote(details, false, "",
            std::to_string(lines_and_points) + " line ('l') and point ('p') records were ignored");
  }
  return builder.Finish(path, options, "OBJ", details);
}

void WriteObj(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "# ergo triangle mesh, " << mesh.vertices.rows() << " vertices, "
        << mesh.triangles.rows() << " triangles, unit "
        << (options.unit == LengthUnit::kMillimetre ? "mm" : "m") << "\n";
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      out << "v";
      for (int k = 0; k < 3; ++k) {
        out << ' ';
        WriteDouble(out, mesh.vertices(v, k) / metres_per_unit);
      }
      out << '\n';
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      out << "f " << mesh.triangles(f, 0) + 1 << ' ' << mesh.triangles(f, 1) + 1 << ' '
          << mesh.triangles(f, 2) + 1 << '\n';
    }
  });
}

}  // namespace ergo
