// Signed distance to a closed triangle surface (the body's skin, paper §3.1): the closest
// surface point by a CGAL AABB tree and the side by a ray-parity inside test, so the skin
// can be used as an implicit function (negative inside) for meshing the tissue layer.
// Metres. CGAL stays inside surface_distance.cc.
#pragma once

#include <memory>
#include <optional>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

class SurfaceDistance {
 public:
  struct Closest {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // closest point on the surface
    int triangle = -1;                                // its triangle
    double distance = 0;                              // unsigned, metres
  };

  // Builds the trees. The surface should be closed for Inside() and Signed() to be
  // meaningful (parity of ray crossings); Closest() works on any surface. Pinched vertices
  // are split (split_non_manifold_vertices.h); a non-manifold edge or inconsistent
  // orientation throws InputError.
  explicit SurfaceDistance(const TriMesh& surface);
  ~SurfaceDistance();
  SurfaceDistance(SurfaceDistance&&) noexcept;
  SurfaceDistance& operator=(SurfaceDistance&&) noexcept;

  // All queries are const and thread-safe.
  Closest Nearest(const Eigen::Vector3d& p) const;
  // The nearest point if it is within `radius` of p, else nullopt. Much faster than
  // Nearest() far from the surface (deep inside a body all triangles are about equally
  // far and a closest-point search visits most of them).
  std::optional<Closest> NearestWithin(const Eigen::Vector3d& p, double radius) const;
  // True when p is strictly inside the closed surface (points on it count as outside).
  bool Inside(const Eigen::Vector3d& p) const;
  // Signed distance: negative inside. *closest receives the closest point when not null.
  double Signed(const Eigen::Vector3d& p, Closest* closest = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ergo
