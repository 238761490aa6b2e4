// The support's top seen along y (up): the largest edge-connected patch of the support's
// triangles whose outward normal points up (n_y ≥ min_normal_y · |n|), as a surface of its
// own. The paper interpolates its measured sensor pressures "onto the vertices of the shoe
// sole" (§6); this patch is that domain, and Locate puts a sensor's (x, z) on it. Metres.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "ergo/ergonomics/planar_triangle_locator.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

class SupportTop {
 public:
  // Throws InputError naming `source` when the support has no upward-facing triangle.
  // min_normal_y = 0.5: faces up to 60° from horizontal (a sculpted sole's slopes; the
  // rim's walls and the bottom are left out).
  SupportTop(const TriMesh& support, const std::string& source, double min_normal_y = 0.5);

  const TriMesh& surface() const { return surface_; }
  // Top vertex → support vertex.
  const Eigen::VectorXi& support_vertex() const { return support_vertex_; }
  // Barycentric vertex areas of the top, m².
  const Eigen::VectorXd& vertex_areas() const { return vertex_areas_; }

  // The point of the top seen at (x, z) from above (the highest triangle there, should the
  // top fold over itself): false when (x, z) lies outside the top.
  bool Locate(const Eigen::Vector2d& xz, PlanarHit* hit) const;
  // Its bounding box seen from above, m.
  const Eigen::Vector2d& lower() const { return locator_->lower(); }
  const Eigen::Vector2d& upper() const { return locator_->upper(); }

 private:
  TriMesh surface_;
  Eigen::VectorXi support_vertex_;
  Eigen::VectorXd vertex_areas_;
  std::shared_ptr<const PlanarTriangleLocator> locator_;
};

}  // namespace ergo
