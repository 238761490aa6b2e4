#include "ergo/mesh/off_format.h"

#include <cctype>
#include <string_view>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

// Fewest bytes a vertex ("0 0 0") and a face ("1 0") can take, to bound header counts.
constexpr uint64_t kMinVertexBytes = 5;
constexpr uint64_t kMinFaceBytes = 3;

bool AllDigits(std::string_view text) {
  if (text.empty()) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

// Reads the header keyword and the counts line; returns the counts' tokens.
std::vector<std::string_view> ReadOffHeader(TextReader& reader) {
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('#', &tokens)) {
    reader.Fail("the file has no OFF header (only blank or comment lines)",
                "start the file with 'OFF' and a line 'vertices faces edges'");
  }
  std::string_view keyword = tokens[0];
  int64_t number = 0;
  if (ParseInt64(keyword, &number)) return tokens;  // keyword-less OFF: counts come first
  const size_t off = keyword.find("OFF");
  if (off == std::string_view::npos) {
    reader.Fail("not an OFF file: it starts with " + Quote(keyword),
                "check the file's format; OFF files start with 'OFF'");
  }
  const std::string_view prefix = keyword.substr(0, off);
  if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos) {
    reader.Fail("this is a " + Quote(keyword) + " file (4-D or n-D points), not a 3-D surface",
                "export the surface as plain 3-D OFF");
  }
  for (char c : prefix) {
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N') {
      reader.Fail("unknown OFF header keyword " + Quote(keyword),
                  "use one of OFF, COFF, NOFF, CNOFF, STOFF");
    }
  }
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
  const std::string_view glued = keyword.substr(off + 3);
  if (!glued.empty()) {
    if (!AllDigits(glued)) {
      reader.Fail("unknown OFF header keyword " + Quote(keyword),
                  "use one of OFF, COFF, NOFF, CNOFF, STOFF");
    }
    counts.insert(counts.begin(), glued);  // "OFF8 6 12": a count glued to the keyword
  }
  if (!counts.empty() && ToLower(counts[0]) == "binary") {
    reader.Fail("binary OFF is not supported", "save the mesh as ASCII OFF, PLY or STL");
  }
  if (counts.empty() && !reader.NextTokens('#', &counts)) {
    reader.Fail("the file ends after the OFF keyword; the counts line is missing",
                "add a line 'vertices faces edges' after 'OFF'");
  }
  return counts;
}

}  // namespace

TriMesh ReadOff(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  const std::vector<std::string_view> counts = ReadOffHeader(reader);
  if (counts.size() < 2) {
    reader.Fail("the counts line needs at least 'vertices faces', found " +
                    std::to_string(counts.size()) + " number(s)",
                "write the counts as 'vertices faces edges'");
  }
  const int64_t vertex_count = ParseInteger(reader, counts[0], "vertex count");
  const int64_t face_count = ParseInteger(reader, counts[1], "face count");
  const std::string counts_location = reader.Location();
  RequireCountFits(path, counts_location, "vertices", vertex_count, kMinVertexBytes,
                   reader.remaining_bytes());
  RequireCountFits(path, counts_location, "faces", face_count, kMinFaceBytes,
                   reader.remaining_bytes());

  SurfaceBuilder builder;
  builder.Reserve(vertex_count, face_count);
  std::vector<std::string_view> tokens;
  for (int64_t v = 0; v < vertex_count; ++v) {
    if (!reader.NextTokens('#', &tokens)) {
      reader.Fail("the file ends after " + std::to_string(v) + " of the " +
                      std::to_string(vertex_count) + " vertices the header declares",
                  "the file is truncated or the header's vertex count is wrong: re-export it");
    }
    if (tokens.size() < 3) {
      reader.Fail("vertex " + std::to_string(v) + " has " + std::to_string(tokens.size()) +
                      " coordinates instead of 3",
                  "check the header's vertex count and the vertex lines");
    }
    const double x = ParseCoordinate(reader, tokens[0], v);
    const double y = ParseCoordinate(reader, tokens[1], v);
    const double z = ParseCoordinate(reader, tokens[2], v);
    builder.AddVertex(x, y, z, reader.line_number());
  }

  TokenStream stream(&reader, '#');
  std::vector<int> corners;
  std::string_view token;
  for (int64_t f = 0; f < face_count; ++f) {
    const std::string face = "face " + std::to_string(f);
    if (!stream.Next(&token)) {
      reader.Fail("the file ends after " + std::to_string(f) + " of the " +
                      std::to_string(face_count) + " faces the header declares",
                  "the file is truncated or the header's face count is wrong: re-export it");
    }
    const int face_line = reader.line_number();
    const int64_t n = ParseInteger(reader, token, face + "'s vertex count");
    if (n <= 0) {
      reader.Fail(face + " has " + std::to_string(n) + " vertices",
                  "every face record is 'n i1 ... in' with n >= 3");
    }
    // n indices take at least 2n - 1 bytes: one digit each, a separator between them.
    RequireCountFits(path, reader.Location(), "vertices in " + face, n, 2,
                     stream.remaining_bytes() + 1);
    corners.clear();
    for (int64_t k = 0; k < n; ++k) {
      if (!stream.Next(&token)) {
        reader.Fail("the file ends inside " + face + " (" + std::to_string(k) + " of " +
                        std::to_string(n) + " indices)",
                    "the file is truncated: re-export it");
      }
      const int64_t index = ParseInteger(reader, token, "vertex index of " + face);
      RequireVertexIndex(path, reader.Location(), face, index, index, vertex_count);
      corners.push_back(static_cast<int>(index));
    }
    stream.SkipRestOfLine();  // face colours
    builder.AddPolygon(corners.data(), static_cast<int>(n), face_line,
                       "line " + std::to_string(face_line));
  }
  if (stream.Next(&token)) {
    AddNote(
        details, false, reader.Location(),
        "data after the last of the " + std::to_string(face_count) + " declared faces was ignored");
  }
  return builder.Finish(path, options, "OFF", details);
}

void WriteOff(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "OFF\n# ergo triangle mesh, unit "
        << (options.unit == LengthUnit::kMillimetre ? "mm" : "m") << "\n"
        << mesh.vertices.rows() << ' ' << mesh.triangles.rows() << " 0\n";
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      for (int k = 0; k < 3; ++k) {
        if (k > 0) out << ' ';
        WriteDouble(out, mesh.vertices(v, k) / metres_per_unit);
      }
      out << '\n';
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      out << "3 " << mesh.triangles(f, 0) << ' ' << mesh.triangles(f, 1) << ' '
          << mesh.triangles(f, 2) << '\n';
    }
  });
}

}  // namespace ergo
