// What every mesh reader shares: parsing coordinates and indices with messages that name
// the line and the element, refusing NaN/Inf, checking a header's counts against the bytes
// left in the file before anything is allocated, and a surface builder that fan-triangulates
// polygons, tallies what it did as notes, and scales the result to metres.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

// Parses a coordinate of `vertex` (0-based); throws naming the line when the token is not a
// number or not finite.
double ParseCoordinate(const TextReader& reader, std::string_view token, int64_t vertex);

// Parses an integer count or index; throws naming the line and `what` otherwise.
int64_t ParseInteger(const TextReader& reader, std::string_view token, const std::string& what);

// Throws unless all three coordinates are finite; `location` is "vertex 5" or "line 12".
void RequireFinite(const std::string& path, const std::string& location, int64_t vertex, double x,
                   double y, double z);

// Throws when `count` items of at least `min_bytes_each` bytes cannot fit in `bytes_left`
// (wrong header or truncated file), when count is negative, or above the int index range.
void RequireCountFits(const std::string& path, const std::string& location,
                      const std::string& items, int64_t count, uint64_t min_bytes_each,
                      uint64_t bytes_left);

// Throws naming the element and line when `index` is outside [0, vertex_count).
// `shown_index` is the index as the file wrote it (1-based for OBJ, for instance).
void RequireVertexIndex(const std::string& path, const std::string& location,
                        const std::string& element, int64_t index, int64_t shown_index,
                        int64_t vertex_count);

// Collects vertices (file units) and polygons, and produces the TriMesh in metres.
class SurfaceBuilder {
 public:
  void AddVertex(double x, double y, double z, int line);
  int64_t vertex_count() const { return static_cast<int64_t>(xyz_.size() / 3); }

  // Adds a polygon of `n` 0-based corners that were already range-checked. Triangles are
  // kept, larger polygons fan-triangulated (counted for a note), and polygons with fewer
  // than 3 corners skipped (counted for a problem note). `location` names it in notes.
  void AddPolygon(const int* corners, int n, int line, const std::string& location);
  int64_t triangle_count() const { return static_cast<int64_t>(corners_.size() / 3); }

  // Reserves room, capped by the caller's already validated counts.
  void Reserve(int64_t vertices, int64_t triangles);

  // The mesh in metres; fills *details (notes, lines). Throws when there are no vertices or
  // no triangles (a point cloud or a line drawing is not a surface).
  TriMesh Finish(const std::string& path, const ReadOptions& options, const std::string& format,
                 ReadDetails* details);

 private:
  std::vector<double> xyz_;
  std::vector<int> corners_;
  std::vector<int> vertex_lines_, triangle_lines_;
  int64_t polygons_split_ = 0, largest_polygon_ = 0;
  std::string first_polygon_;
  int64_t short_faces_ = 0;
  std::string first_short_face_;
};

// Multiplies coordinates by the unit's metres per unit.
void ScaleToMetres(const ReadOptions& options, Vertices* vertices);

// Appends a note to *details (nothing when details is null).
void AddNote(ReadDetails* details, bool is_problem, std::string location, std::string what,
             std::string fix = "");

}  // namespace ergo
