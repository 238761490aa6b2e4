#include "ergo/body/tet_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace ergo {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                              {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};

}  // namespace

std::array<double, 6> DihedralAngles(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  const Eigen::Vector3d* p[4] = {&p0, &p1, &p2, &p3};
  std::array<double, 6> angles{};
  for (int e = 0; e < 6; ++e) {
    const Eigen::Vector3d& a = *p[kEdges[e][0]];
    const Eigen::Vector3d edge = *p[kEdges[e][1]] - a;
    const double length2 = edge.squaredNorm();
    if (!(length2 > 0)) continue;
    // The angle between the two faces at this edge is the angle between the other two
    // corners' offsets from the edge line, seen along the edge.
    Eigen::Vector3d u = *p[kEdges[e][2]] - a, v = *p[kEdges[e][3]] - a;
    u -= edge * (u.dot(edge) / length2);
    v -= edge * (v.dot(edge) / length2);
    angles[e] = std::atan2(u.cross(v).norm(), u.dot(v)) * kDegreesPerRadian;
  }
  return angles;
}

double RadiusRatio(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3) {
  const Eigen::Vector3d a = p1 - p0, b = p2 - p0, c = p3 - p0;
  const double six_volume = a.dot(b.cross(c));
  if (six_volume == 0) return 0;
  // Inradius r = 3V / (total face area); circumradius R = |a²(b×c) + b²(c×a) + c²(a×b)| / 12V.
  const double face_area2 = b.cross(c).norm() + a.cross(b).norm() + c.cross(a).norm() +
                            (b - a).cross(c - a).norm();  // twice the total area
  const double r = std::abs(six_volume) / face_area2;     // 3V / area = 6V / (2 area)
  const double R =
      (a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b))
          .norm() /
      (2.0 * std::abs(six_volume));
  const double ratio = 3.0 * r / R;
  return six_volume > 0 ? ratio : -ratio;
}

TetQuality MeasureTetQuality(const TetMesh& mesh) {
  TetQuality q;
  q.tet_count = static_cast<int>(mesh.tets.rows());
  if (q.tet_count == 0) return q;
  q.min_dihedral_degrees = std::numeric_limits<double>::infinity();
  q.max_dihedral_degrees = 0;
  q.min_radius_ratio = std::numeric_limits<double>::infinity();
  q.min_volume = std::numeric_limits<double>::infinity();
  q.max_volume = -std::numeric_limits<double>::infinity();
  double ratio_sum = 0;
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<size_t>(q.tet_count) * 6);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    Eigen::Vector3d p[4];
    for (int k = 0; k < 4; ++k) p[k] = mesh.vertices.row(mesh.tets(t, k)).transpose();
    const double volume = (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) / 6.0;
    if (!(volume > 0)) ++q.non_positive_count;
    q.min_volume = std::min(q.min_volume, volume);
    q.max_volume = std::max(q.max_volume, volume);
    const double ratio = RadiusRatio(p[0], p[1], p[2], p[3]);
    q.min_radius_ratio = std::min(q.min_radius_ratio, ratio);
    ratio_sum += ratio;
    for (double angle : DihedralAngles(p[0], p[1], p[2], p[3])) {
      q.min_dihedral_degrees = std::min(q.min_dihedral_degrees, angle);
      q.max_dihedral_degrees = std::max(q.max_dihedral_degrees, angle);
    }
    for (const auto& e : kEdges) {
      const int i = mesh.tets(t, e[0]), j = mesh.tets(t, e[1]);
      edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  q.mean_radius_ratio = ratio_sum / q.tet_count;
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double length_sum = 0;
  q.min_edge_length = std::numeric_limits<double>::infinity();
  for (const auto& [i, j] : edges) {
    const double length = (mesh.vertices.row(i) - mesh.vertices.row(j)).norm();
    length_sum += length;
    q.min_edge_length = std::min(q.min_edge_length, length);
    q.max_edge_length = std::max(q.max_edge_length, length);
  }
  q.mean_edge_length = length_sum / static_cast<double>(edges.size());
  return q;
}

}  // namespace ergo
