#include "ergo/ergonomics/linearly_precise_laplacian.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "ergo/mesh/cotangent_stiffness.h"

namespace ergo {

SparseMatrix BoundaryFluxMatrix(const TriMesh& surface) {
  const Eigen::Index n = surface.vertices.rows();
  // An edge is on the boundary when one triangle alone has it (either orientation).
  std::map<std::pair<int, int>, int> edge_count;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = surface.triangles(f, k), b = surface.triangles(f, (k + 1) % 3);
      ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const int v[3] = {surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2)};
    const Eigen::Vector3d p[3] = {surface.vertices.row(v[0]), surface.vertices.row(v[1]),
                                  surface.vertices.row(v[2])};
    const Eigen::Vector3d normal2 = (p[1] - p[0]).cross(p[2] - p[0]);  // 2A times the unit normal
    const double twice_area = normal2.norm();
    if (!(twice_area > 0)) continue;
    const Eigen::Vector3d unit_normal = normal2 / twice_area;
    // ∇φ_k = n × (p_{k+2} − p_{k+1}) / 2A: perpendicular to the opposite edge, towards p_k.
    Eigen::Vector3d gradient[3];
    for (int k = 0; k < 3; ++k)
      gradient[k] = unit_normal.cross(p[(k + 2) % 3] - p[(k + 1) % 3]) / twice_area;
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      if (edge_count[{std::min(a, b), std::max(a, b)}] != 1) continue;
      // Outward normal of edge (a, b) in the triangle's plane: away from the opposite corner.
      const Eigen::Vector3d edge = p[(k + 1) % 3] - p[k];
      const double length = edge.norm();
      const Eigen::Vector3d away = p[k] - p[(k + 2) % 3];
      Eigen::Vector3d outward = away - away.dot(edge) / (length * length) * edge;
      outward.normalize();
      // ∮_e (∇u·n) φ_i = (|e|/2) n·∇u for both ends i of the edge.
      for (int corner = 0; corner < 3; ++corner) {
        const double flux = 0.5 * length * outward.dot(gradient[corner]);
        entries.emplace_back(a, v[corner], flux);
        entries.emplace_back(b, v[corner], flux);
      }
    }
  }
  SparseMatrix flux(n, n);
  flux.setFromTriplets(entries.begin(), entries.end());
  return flux;
}

SparseMatrix LinearlyPreciseLaplacian(const TriMesh& surface) {
  const SparseMatrix laplacian =
      BoundaryFluxMatrix(surface) - CotangentStiffness(surface.triangles, surface.vertices);
  return laplacian.pruned();
}

}  // namespace ergo
