#include "ergo/mesh/read_support.h"

#include <cmath>
#include <limits>
#include <utility>

#include "ergo/mesh/input_error.h"

namespace ergo {

namespace {

constexpr int64_t kMaxIndexCount = std::numeric_limits<int>::max();

std::string NumberText(double value) {
  if (std::isnan(value)) return "NaN";
  return value > 0 ? "+infinity" : "-infinity";
}

}  // namespace

double ParseCoordinate(const TextReader& reader, std::string_view token, int64_t vertex) {
  double value = 0;
  if (!ParseDouble(token, &value)) {
    reader.Fail(
        "coordinate " + Quote(token) + " of vertex " + std::to_string(vertex) + " is not a number",
        "write coordinates as decimal numbers such as -1.25e-3");
  }
  if (!std::isfinite(value)) {
    reader.Fail("vertex " + std::to_string(vertex) + " has a " + NumberText(value) +
                    " coordinate (" + Quote(token) + ")",
                "repair the mesh in the program that made it: every coordinate must be finite");
  }
  return value;
}

int64_t ParseInteger(const TextReader& reader, std::string_view token, const std::string& what) {
  int64_t value = 0;
  if (!ParseInt64(token, &value)) {
    reader.Fail(what + " " + Quote(token) + " is not an integer",
                "check the file against its format; it may be corrupt or truncated");
  }
  return value;
}

void RequireFinite(const std::string& path, const std::string& location, int64_t vertex, double x,
                   double y, double z) {
  for (double value : {x, y, z}) {
    if (!std::isfinite(value)) {
      throw InputError(
          path, location,
          "vertex " + std::to_string(vertex) + " has a " + NumberText(value) + " coordinate",
          "repair the mesh in the program that made it: every coordinate must be "
          "finite");
    }
  }
}

void RequireCountFits(const std::string& path, const std::string& location,
                      const std::string& items, int64_t count, uint64_t min_bytes_each,
                      uint64_t bytes_left) {
  if (count < 0) {
    throw InputError(path, location, "the header declares a negative number of " + items,
                     "fix the count in the header or re-export the mesh");
  }
  if (count > kMaxIndexCount) {
    throw InputError(path, location,
                     "the header declares " + std::to_string(count) + " " + items +
                         ", more than ergo can index (2^31 - 1)",
                     "fix the count in the header, or split the mesh");
  }
  if (min_bytes_each > 0 && static_cast<uint64_t>(count) > bytes_left / min_bytes_each) {
    throw InputError(path, location,
                     "the header declares " + std::to_string(count) + " " + items +
                         ", which need at least " +
                         std::to_string(static_cast<uint64_t>(count) * min_bytes_each) +
                         " bytes, but only " + std::to_string(bytes_left) +
                         " bytes follow: the count is wrong or the file is truncated",
                     "re-export the mesh, or correct the count in the header");
  }
}

void RequireVertexIndex(const std::string& path, const std::string& location,
                        const std::string& element, int64_t index, int64_t shown_index,
                        int64_t vertex_count) {
  if (index >= 0 && index < vertex_count) return;
  throw InputError(path, location,
                   element + " refers to vertex " + std::to_string(shown_index) +
                       ", but the file has " + std::to_string(vertex_count) + " vertices" +
                       (index < 0 ? " (the index is below the first vertex)" : ""),
                   "re-export the mesh; every face index must name an existing vertex");
}

void SurfaceBuilder::AddVertex(double x, double y, double z, int line) {
  xyz_.push_back(x);
  xyz_.push_back(y);
  xyz_.push_back(z);
  if (line > 0) vertex_lines_.push_back(line);
}

void SurfaceBuilder::AddPolygon(const int* corners, int n, int line, const std::string& location) {
  if (n < 3) {
    if (short_faces_++ == 0) first_short_face_ = location;
    return;
  }
  if (n > 3) {
    if (polygons_split_++ == 0) first_polygon_ = location;
    if (n > largest_polygon_) largest_polygon_ = n;
  }
  for (int k = 1; k + 1 < n; ++k) {
    corners_.push_back(corners[0]);
    corners_.push_back(corners[k]);
    corners_.push_back(corners[k + 1]);
    if (line > 0) triangle_lines_.push_back(line);
  }
}

void SurfaceBuilder::Reserve(int64_t vertices, int64_t triangles) {
  xyz_.reserve(static_cast<size_t>(3 * vertices));
  corners_.reserve(static_cast<size_t>(3 * triangles));
}

TriMesh SurfaceBuilder::Finish(const std::string& path, const ReadOptions& options,
                               const std::string& format, ReadDetails* details) {
  const int64_t vertex_count = static_cast<int64_t>(xyz_.size() / 3);
  const int64_t triangle_count = static_cast<int64_t>(corners_.size() / 3);
  if (vertex_count == 0) {
    throw InputError(path, "", "the file holds no vertices and no faces (" + format + ")",
                     "export the surface again; this file describes an empty mesh");
  }
  if (triangle_count == 0) {
    throw InputError(path, "",
                     "the file has " + std::to_string(vertex_count) +
                         " vertices but no faces: a point cloud or a line drawing is not a "
                         "surface (" +
                         format + ")",
                     "export the surface as triangles or polygons");
  }
  TriMesh mesh;
  mesh.vertices = Eigen::Map<const Vertices>(xyz_.data(), vertex_count, 3);
  mesh.triangles = Eigen::Map<const Triangles>(corners_.data(), triangle_count, 3);
  ScaleToMetres(options, &mesh.vertices);
  if (details) {
    details->format = format;
    if (polygons_split_ > 0) {
      AddNote(details, false, first_polygon_,
              Counted(polygons_split_, "polygon with more than 3 vertices was",
                      "polygons with more than 3 vertices were") +
                  " split into triangles (fan; largest: " + std::to_string(largest_polygon_) +
                  " vertices)");
    }
    if (short_faces_ > 0) {
      AddNote(details, true, first_short_face_,
              Counted(short_faces_, "face with fewer than 3 vertices was",
                      "faces with fewer than 3 vertices were") +
                  " skipped (they are lines or points)",
              "remove them, or export the surface as triangles");
    }
    if (static_cast<int64_t>(vertex_lines_.size()) == vertex_count) {
      details->vertex_lines = std::move(vertex_lines_);
    }
    if (static_cast<int64_t>(triangle_lines_.size()) == triangle_count) {
      details->element_lines = std::move(triangle_lines_);
    }
  }
  return mesh;
}

void ScaleToMetres(const ReadOptions& options, Vertices* vertices) {
  const double scale = MetresPerUnit(options.unit);
  if (scale != 1.0) *vertices *= scale;
}

void AddNote(ReadDetails* details, bool is_problem, std::string location, std::string what,
             std::string fix) {
  if (!details) return;
  details->notes.push_back({is_problem, std::move(location), std::move(what), std::move(fix)});
}

}  // namespace ergo
