#include "ergo/mesh/split_non_manifold_vertices.h"

#include <numeric>
#include <vector>

namespace ergo {
namespace {

int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

TriMesh SplitNonManifoldVertices(const TriMesh& surface, int* split_count) {
  TriMesh result = surface;
  const Eigen::Index n = surface.vertices.rows();
  std::vector<std::vector<int>> incident(n);
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) incident[surface.triangles(f, k)].push_back(static_cast<int>(f));
  std::vector<Eigen::RowVector3d> added;
  for (Eigen::Index v = 0; v < n; ++v) {
    const std::vector<int>& faces = incident[v];
    if (faces.size() < 2) continue;
    // Fans: faces around v joined when they share an edge through v (another common vertex).
    std::vector<int> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (size_t a = 0; a < faces.size(); ++a) {
      for (size_t b = a + 1; b < faces.size(); ++b) {
        int common = 0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            common += surface.triangles(faces[a], i) == surface.triangles(faces[b], j);
        if (common >= 2)
          parent[Root(parent, static_cast<int>(a))] = Root(parent, static_cast<int>(b));
      }
    }
    const int first = Root(parent, 0);
    std::vector<int> copy_of_root(faces.size(), -1);
    for (size_t a = 0; a < faces.size(); ++a) {
      const int root = Root(parent, static_cast<int>(a));
      if (root == first) continue;
      if (copy_of_root[root] < 0) {
        copy_of_root[root] = static_cast<int>(n + added.size());
        added.push_back(surface.vertices.row(v));
      }
      for (int k = 0; k < 3; ++k)
        if (result.triangles(faces[a], k) == v) result.triangles(faces[a], k) = copy_of_root[root];
    }
  }
  if (!added.empty()) {
    result.vertices.conservativeResize(n + static_cast<Eigen::Index>(added.size()), 3);
    for (size_t i = 0; i < added.size(); ++i) result.vertices.row(n + i) = added[i];
  }
  if (split_count != nullptr) *split_count = static_cast<int>(added.size());
  return result;
}

}  // namespace ergo
