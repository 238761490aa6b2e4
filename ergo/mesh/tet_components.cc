#include "ergo/mesh/tet_components.h"

#include <numeric>
#include <vector>

namespace ergo {
namespace {

int Root(std::vector<int>* parent, int v) {
  while ((*parent)[v] != v) v = (*parent)[v] = (*parent)[(*parent)[v]];  // path halving
  return v;
}

}  // namespace

TetComponents LabelTetComponents(const TetMesh& mesh) {
  const auto n = static_cast<int>(mesh.vertices.rows());
  std::vector<int> parent(static_cast<size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> used(static_cast<size_t>(n), false);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int k = 0; k < 4; ++k) used[mesh.tets(t, k)] = true;
    for (int k = 1; k < 4; ++k) {
      const int a = Root(&parent, mesh.tets(t, 0)), b = Root(&parent, mesh.tets(t, k));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the lowest vertex is the root
    }
  }
  TetComponents out;
  out.vertex_component = Eigen::VectorXi::Constant(n, -1);
  std::vector<int> label(static_cast<size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    if (!used[v]) continue;
    const int root = Root(&parent, v);
    if (label[root] < 0) label[root] = out.count++;
    out.vertex_component[v] = label[root];
  }
  return out;
}

}  // namespace ergo
