// Internal to the mesh check (mesh_check.h): the context every check step shares (how to
// name vertices and elements in messages, how to tally a finding with a few examples) and
// the steps themselves: vertex checks in mesh_check.cc, surface checks in
// mesh_check_surface.cc, tetrahedron checks in mesh_check_volume.cc.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ergo/mesh/mesh_check.h"

namespace ergo::check {

// A triangle's height below this fraction of its longest edge, or a tet's |6V| below this
// fraction of its longest edge cubed, is a degenerate shape to working precision.
constexpr double kDegenerateShape = 1e-10;

struct Context {
  const std::string& source;
  const MeshCheckOptions& options;
  const ReadDetails* details;  // may be null

  // "vertex 12 (line 40)" or "vertex 12".
  std::string Vertex(int64_t v) const;
  // "triangle 5 (line 17)" for kind "triangle", and likewise for tets.
  std::string Element(const char* kind, int64_t e) const;
};

// Tallies one kind of finding: counts every occurrence, keeps the first few examples.
class Tally {
 public:
  Tally(Severity severity, std::string code, int max_examples)
      : severity_(severity), code_(std::move(code)), max_examples_(max_examples) {}
  void Add(const std::string& example) {
    if (static_cast<int>(examples_.size()) < max_examples_) examples_.push_back(example);
    ++count_;
  }
  // Add() without building the example string once enough examples are kept.
  bool WantsExample() const { return static_cast<int>(examples_.size()) < max_examples_; }
  void Count() { ++count_; }
  int64_t count() const { return count_; }
  // Appends the finding to the report when anything was counted.
  void Report(const std::string& what, const std::string& fix, MeshCheckReport* report) const;

 private:
  Severity severity_;
  std::string code_;
  int max_examples_;
  int64_t count_ = 0;
  std::vector<std::string> examples_;
};

// Maps every vertex to the first vertex at exactly the same position (itself if none) and
// reports coincident vertices among those in `used`.
std::vector<int> CheckCoincidentVertices(const Vertices& vertices, const std::vector<bool>& used,
                                         const Context& context, MeshCheckReport* report);

// Notes unused vertices; checks the bounding box of the used ones for a wrong unit.
void CheckVertexUse(const Vertices& vertices, const std::vector<bool>& used, const Context& context,
                    MeshCheckReport* report);

// Triangle-surface checks; `weld` from CheckCoincidentVertices.
void CheckSurface(const TriMesh& mesh, const std::vector<int>& weld, const Context& context,
                  MeshCheckReport* report);

// Tetrahedron checks.
void CheckVolume(const TetMesh& mesh, const Context& context, MeshCheckReport* report);

// Lengths, areas and volumes of the checks are computed in long double, whose exponent range
// (to 1e4932 on x86-64 and aarch64) holds the squares and cubes of any finite double: a mesh
// with coordinates of 1e300 gets its true size and shapes instead of infinities.
using WideVector = Eigen::Matrix<long double, 3, 1>;
static_assert(std::numeric_limits<long double>::max_exponent10 >
                  3 * std::numeric_limits<double>::max_exponent10,
              "the mesh check needs a long double that holds the cube of any double");
inline WideVector WidePoint(const Vertices& vertices, Eigen::Index v) {
  return vertices.row(v).transpose().cast<long double>();
}

// Hash of an element's sorted vertex ids, to find duplicate elements in linear time.
struct VertexIdsHash {
  template <size_t N>
  size_t operator()(const std::array<int, N>& ids) const {
    uint64_t hash = 0x9E3779B97F4A7C15u;
    for (const int id : ids) {
      hash = (hash ^ static_cast<uint32_t>(id)) * 0xFF51AFD7ED558CCDu;
      hash ^= hash >> 32;
    }
    return static_cast<size_t>(hash);
  }
};

// "(0.1, -0.25, 3)" in metres.
std::string FormatPoint(const Eigen::Vector3d& p);

}  // namespace ergo::check
