#include "ergo/ergonomics/support_top_surface.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

SupportTop::SupportTop(const TriMesh& support, const std::string& source, double min_normal_y) {
  std::vector<int> up;
  for (Eigen::Index f = 0; f < support.triangles.rows(); ++f) {
    const Eigen::Vector3d a = support.vertices.row(support.triangles(f, 0));
    const Eigen::Vector3d b = support.vertices.row(support.triangles(f, 1));
    const Eigen::Vector3d c = support.vertices.row(support.triangles(f, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() > 0 && normal.y() >= min_normal_y * normal.norm())
      up.push_back(static_cast<int>(f));
  }
  if (up.empty()) {
    throw InputError(source, "", "the support has no upward-facing surface to carry a measured map",
                     "the support's top must face +y (ergo's frame: y up)");
  }
  // Edge-connected components of the upward faces (union-find over shared edges).
  std::vector<int> parent(up.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, int> first_face_of_edge;
  for (size_t k = 0; k < up.size(); ++k) {
    for (int e = 0; e < 3; ++e) {
      const int a = support.triangles(up[k], e), b = support.triangles(up[k], (e + 1) % 3);
      const auto [it, inserted] = first_face_of_edge.emplace(
          std::make_pair(std::min(a, b), std::max(a, b)), static_cast<int>(k));
      if (!inserted) parent[Root(parent, static_cast<int>(k))] = Root(parent, it->second);
    }
  }
  const Eigen::VectorXd face_areas = TriangleAreas(support);
  std::map<int, double> component_area;
  for (size_t k = 0; k < up.size(); ++k)
    component_area[Root(parent, static_cast<int>(k))] += face_areas[up[k]];
  const int largest =
      std::max_element(component_area.begin(), component_area.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; })
          ->first;
  std::vector<int> local(static_cast<size_t>(support.vertices.rows()), -1);
  std::vector<int> support_vertex;
  std::vector<int> faces;
  for (size_t k = 0; k < up.size(); ++k) {
    if (Root(parent, static_cast<int>(k)) != largest) continue;
    faces.push_back(up[k]);
    for (int e = 0; e < 3; ++e) {
      const int v = support.triangles(up[k], e);
      if (local[v] < 0) {
        local[v] = static_cast<int>(support_vertex.size());
        support_vertex.push_back(v);
      }
    }
  }
  surface_.vertices.resize(static_cast<Eigen::Index>(support_vertex.size()), 3);
  support_vertex_.resize(static_cast<Eigen::Index>(support_vertex.size()));
  for (size_t i = 0; i < support_vertex.size(); ++i) {
    surface_.vertices.row(static_cast<Eigen::Index>(i)) = support.vertices.row(support_vertex[i]);
    support_vertex_[static_cast<Eigen::Index>(i)] = support_vertex[i];
  }
  surface_.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t k = 0; k < faces.size(); ++k)
    for (int e = 0; e < 3; ++e)
      surface_.triangles(static_cast<Eigen::Index>(k), e) = local[support.triangles(faces[k], e)];
  vertex_areas_ = BarycentricVertexAreas(surface_);
  PlanarPoints points(surface_.vertices.rows(), 2);
  points.col(0) = surface_.vertices.col(0);
  points.col(1) = surface_.vertices.col(2);
  locator_ = std::make_shared<const PlanarTriangleLocator>(points, surface_.triangles);
}

bool SupportTop::Locate(const Eigen::Vector2d& xz, PlanarHit* hit) const {
  std::vector<PlanarHit> hits;
  locator_->Locate(xz, &hits);
  double best_height = -std::numeric_limits<double>::infinity();
  for (const PlanarHit& candidate : hits) {
    double height = 0;
    for (int k = 0; k < 3; ++k)
      height += candidate.barycentric[k] *
                surface_.vertices(surface_.triangles(candidate.triangle, k), 1);
    if (height > best_height) {
      best_height = height;
      *hit = candidate;
    }
  }
  return !hits.empty();
}

}  // namespace ergo
