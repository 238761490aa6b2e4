#include "ergo/mesh/tet_boundary.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include <glog/logging.h>

namespace ergo {
namespace {

// The face opposite local vertex k, ordered so its normal points away from vertex k for a
// positively oriented tet (v0, v1, v2, v3).
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct FaceRecord {
  std::array<int, 3> sorted;    // key: vertex ids in increasing order
  std::array<int, 3> oriented;  // outward order
  int tet;
};

// Union-find over faces, for edge-connected components.
int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

TetBoundary ExtractBoundary(const TetMesh& mesh) {
  const Eigen::Index tet_count = mesh.tets.rows();
  std::vector<FaceRecord> faces;
  faces.reserve(static_cast<size_t>(tet_count) * 4);
  for (Eigen::Index t = 0; t < tet_count; ++t) {
    for (const auto& local : kFaces) {
      FaceRecord face;
      for (int k = 0; k < 3; ++k) face.oriented[k] = mesh.tets(t, local[k]);
      face.sorted = face.oriented;
      std::sort(face.sorted.begin(), face.sorted.end());
      face.tet = static_cast<int>(t);
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.sorted != b.sorted ? a.sorted < b.sorted : a.tet < b.tet;
  });

  std::vector<const FaceRecord*> boundary;
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].sorted == faces[i].sorted) ++j;
    CHECK_LE(j - i, 2u) << "face shared by " << j - i << " tets: non-manifold tet mesh";
    if (j - i == 1) boundary.push_back(&faces[i]);
    i = j;
  }

  TetBoundary result;
  result.tet_to_surface = Eigen::VectorXi::Constant(mesh.vertices.rows(), -1);
  std::vector<int> surface_vertices;
  for (const FaceRecord* face : boundary)
    for (int v : face->sorted) surface_vertices.push_back(v);
  std::sort(surface_vertices.begin(), surface_vertices.end());
  surface_vertices.erase(std::unique(surface_vertices.begin(), surface_vertices.end()),
                         surface_vertices.end());
  const auto vertex_count = static_cast<Eigen::Index>(surface_vertices.size());
  result.surface_to_tet.resize(vertex_count);
  result.surface.vertices.resize(vertex_count, 3);
  for (Eigen::Index s = 0; s < vertex_count; ++s) {
    result.surface_to_tet[s] = surface_vertices[s];
    result.tet_to_surface[surface_vertices[s]] = static_cast<int>(s);
    result.surface.vertices.row(s) = mesh.vertices.row(surface_vertices[s]);
  }
  const auto face_count = static_cast<Eigen::Index>(boundary.size());
  result.surface.triangles.resize(face_count, 3);
  result.face_tet.resize(face_count);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    for (int k = 0; k < 3; ++k)
      result.surface.triangles(f, k) = result.tet_to_surface[boundary[f]->oriented[k]];
    result.face_tet[f] = boundary[f]->tet;
  }

  // Edge-connected components: faces sharing an undirected edge are joined.
  std::vector<int> parent(static_cast<size_t>(face_count));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::pair<std::pair<int, int>, int>> edge_faces;
  edge_faces.reserve(static_cast<size_t>(face_count) * 3);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = result.surface.triangles(f, k), b = result.surface.triangles(f, (k + 1) % 3);
      edge_faces.push_back({{std::min(a, b), std::max(a, b)}, static_cast<int>(f)});
    }
  }
  std::sort(edge_faces.begin(), edge_faces.end());
  for (size_t i = 1; i < edge_faces.size(); ++i) {
    if (edge_faces[i].first == edge_faces[i - 1].first) {
      parent[Find(parent, edge_faces[i].second)] = Find(parent, edge_faces[i - 1].second);
    }
  }
  result.face_component.assign(static_cast<size_t>(face_count), -1);
  std::vector<int> label(static_cast<size_t>(face_count), -1);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const int root = Find(parent, static_cast<int>(f));
    if (label[root] < 0) label[root] = result.component_count++;
    result.face_component[f] = label[root];
  }
  return result;
}

}  // namespace ergo
