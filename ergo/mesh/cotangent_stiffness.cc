#include "ergo/mesh/cotangent_stiffness.h"

#include <vector>

#include <glog/logging.h>
#include <Eigen/Geometry>

namespace ergo {

SparseMatrix CotangentStiffness(const Triangles& triangles, const Vertices& vertices) {
  const Eigen::Index vertex_count = vertices.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(triangles.rows()) * 12);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    int corner[3];
    for (int k = 0; k < 3; ++k) {
      corner[k] = triangles(f, k);
      CHECK(corner[k] >= 0 && corner[k] < vertex_count) << "index out of range in triangle " << f;
    }
    const Eigen::Vector3d p[3] = {vertices.row(corner[0]).transpose(),
                                  vertices.row(corner[1]).transpose(),
                                  vertices.row(corner[2]).transpose()};
    const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(twice_area > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (i, j).
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double half_cot = 0.5 * (p[i] - p[k]).dot(p[j] - p[k]) / twice_area;
      entries.emplace_back(corner[i], corner[j], -half_cot);
      entries.emplace_back(corner[j], corner[i], -half_cot);
      entries.emplace_back(corner[i], corner[i], half_cot);
      entries.emplace_back(corner[j], corner[j], half_cot);
    }
  }
  SparseMatrix stiffness(vertex_count, vertex_count);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  return stiffness;
}

}  // namespace ergo
