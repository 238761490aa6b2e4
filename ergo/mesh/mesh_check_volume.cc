// Tetrahedral-mesh steps of the mesh check (see mesh_check_steps.h): tets with a repeated
// vertex, zero-volume and inverted tets (negative orientation, the convention of
// tri_mesh.h), duplicate tets (hashing), and faces shared by more than two tets (sorting),
// O(n log n).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include <Eigen/Geometry>

#include "ergo/mesh/mesh_check_steps.h"
#include "ergo/mesh/text_reader.h"

namespace ergo::check {

namespace {

// |6V| below this fraction of the cube of the mesh size is zero (the shape's threshold, a
// fraction of the cube of the longest edge, is kDegenerateShape).
constexpr double kDegenerateVolume = 1e-12;

std::string Corners(const TetMesh& mesh, int t) {
  return "(" + std::to_string(mesh.tets(t, 0)) + ", " + std::to_string(mesh.tets(t, 1)) + ", " +
         std::to_string(mesh.tets(t, 2)) + ", " + std::to_string(mesh.tets(t, 3)) + ")";
}

}  // namespace

void CheckVolume(const TetMesh& mesh, const Context& context, MeshCheckReport* report) {
  const int tets = static_cast<int>(mesh.tets.rows());
  const int examples = context.options.max_examples;
  const double diagonal = report->bounding_box_diagonal;
  Tally repeated(Severity::kProblem, "repeated-vertex-in-tet", examples);
  Tally flat(Severity::kProblem, "zero-volume-tets", examples);
  Tally inverted(Severity::kProblem, "inverted-tets", examples);
  std::vector<bool> valid(static_cast<size_t>(tets), true);
  for (int t = 0; t < tets; ++t) {
    std::array<int, 4> v = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    std::sort(v.begin(), v.end());
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[3]) {
      valid[static_cast<size_t>(t)] = false;
      if (repeated.WantsExample()) {
        repeated.Add(context.Element("tetrahedron", t) + " has vertices " + Corners(mesh, t));
      } else {
        repeated.Count();
      }
      continue;
    }
    const WideVector p0 = WidePoint(mesh.vertices, mesh.tets(t, 0));
    const WideVector e1 = WidePoint(mesh.vertices, mesh.tets(t, 1)) - p0;
    const WideVector e2 = WidePoint(mesh.vertices, mesh.tets(t, 2)) - p0;
    const WideVector e3 = WidePoint(mesh.vertices, mesh.tets(t, 3)) - p0;
    const long double six_volume = e1.dot(e2.cross(e3));
    const long double longest = std::sqrt(
        std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm(), (e2 - e1).squaredNorm(),
                  (e3 - e1).squaredNorm(), (e3 - e2).squaredNorm()}));
    const long double size = diagonal;
    char volume[32];
    std::snprintf(volume, sizeof volume, "%.3Lg", six_volume / 6);
    if (std::fabs(six_volume) <= kDegenerateShape * longest * longest * longest ||
        std::fabs(six_volume) <= kDegenerateVolume * size * size * size) {
      if (flat.WantsExample()) {
        flat.Add(context.Element("tetrahedron", t) + " " + Corners(mesh, t) + " has volume " +
                 volume + " m³");
      } else {
        flat.Count();
      }
    } else if (six_volume < 0) {
      if (inverted.WantsExample()) {
        inverted.Add(context.Element("tetrahedron", t) + " " + Corners(mesh, t) +
                     " has negative volume " + volume + " m³");
      } else {
        inverted.Count();
      }
    }
  }
  repeated.Report(
      Counted(repeated.count(), "tetrahedron uses", "tetrahedra use") + " the same vertex twice",
      "remove these tetrahedra or re-mesh the volume", report);
  flat.Report(Counted(flat.count(), "tetrahedron has", "tetrahedra have") +
                  " zero volume (flat): the stiffness is undefined there",
              "re-mesh the volume with a quality bound (e.g. tetgen -pq1.4, or gmsh's "
              "optimiser)",
              report);
  if (inverted.count() == tets) {
    inverted.Report("all " + std::to_string(tets) +
                        " tetrahedra are inverted (negative orientation): the file uses the "
                        "opposite vertex order",
                    "swap two vertices of every tetrahedron (e.g. the last two), or re-export "
                    "with positive orientation",
                    report);
  } else {
    inverted.Report(Counted(inverted.count(), "tetrahedron is", "tetrahedra are") +
                        " inverted (negative orientation, (v1-v0)·((v2-v0)×(v3-v0)) < 0)",
                    "swap two vertices of each inverted tetrahedron (e.g. the last two), or "
                    "re-mesh",
                    report);
  }

  // Duplicate tets by hashing their sorted vertex ids (each copy against the first), then
  // faces shared by more than two of the remaining tets by sorting.
  std::unordered_map<std::array<int, 4>, int, VertexIdsHash> first_with;
  std::vector<std::pair<std::array<int, 3>, int>> faces;
  first_with.reserve(static_cast<size_t>(tets));
  faces.reserve(4 * static_cast<size_t>(tets));
  Tally duplicate(Severity::kProblem, "duplicate-tets", examples);
  for (int t = 0; t < tets; ++t) {
    if (!valid[static_cast<size_t>(t)]) continue;
    std::array<int, 4> v = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    std::sort(v.begin(), v.end());
    const auto [first, inserted] = first_with.emplace(v, t);
    if (!inserted) {
      if (duplicate.WantsExample()) {
        duplicate.Add(context.Element("tetrahedron", t) + " repeats " +
                      context.Element("tetrahedron", first->second));
      } else {
        duplicate.Count();
      }
      continue;  // copies are left out of the face check
    }
    faces.push_back({{v[1], v[2], v[3]}, t});
    faces.push_back({{v[0], v[2], v[3]}, t});
    faces.push_back({{v[0], v[1], v[3]}, t});
    faces.push_back({{v[0], v[1], v[2]}, t});
  }
  duplicate.Report(Counted(duplicate.count(), "tetrahedron repeats", "tetrahedra repeat") +
                       " an earlier tetrahedron (same four vertices)",
                   "remove the duplicates or re-mesh", report);
  std::sort(faces.begin(), faces.end());
  Tally crowded(Severity::kProblem, "non-manifold-tet-faces", examples);
  for (size_t i = 0; i < faces.size();) {
    size_t j = i;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    if (j - i > 2) {
      if (crowded.WantsExample()) {
        std::string example = "face (" + std::to_string(faces[i].first[0]) + ", " +
                              std::to_string(faces[i].first[1]) + ", " +
                              std::to_string(faces[i].first[2]) + ") is shared by " +
                              std::to_string(j - i) + " tetrahedra: ";
        for (size_t k = i; k < j && k < i + 4; ++k) {
          example += (k == i ? "" : ", ") + context.Element("tetrahedron", faces[k].second);
        }
        crowded.Add(example);
      } else {
        crowded.Count();
      }
    }
    i = j;
  }
  crowded.Report(Counted(crowded.count(), "triangular face is", "triangular faces are") +
                     " shared by more than two tetrahedra (overlapping elements)",
                 "re-mesh the volume; a valid tetrahedral mesh shares each face between at "
                 "most two tetrahedra",
                 report);
}

}  // namespace ergo::check
