// CGAL translation unit: AABB tree closest points and the ray-parity inside test.
#include "ergo/body/surface_distance.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <glog/logging.h>

#include "ergo/mesh/cgal_surface_mesh.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_non_manifold_vertices.h"

namespace ergo {
namespace {

// Distances need no exact predicates (DESIGN.md §6).
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using SideOf = CGAL::Side_of_triangle_mesh<Mesh, Kernel>;
using Tree = SideOf::AABB_tree;

// AABB traversal that stops at the first triangle within a ball (CGAL's Sphere_3 queries
// test the sphere's surface, which misses triangles entirely inside the ball).
struct BallQuery {
  const Mesh* mesh;
  double squared_radius;
  Mesh::Face_index found = Mesh::null_face();

  bool go_further() const { return found == Mesh::null_face(); }

  template <class Primitive>
  void intersection(const Point& centre, const Primitive& primitive) {
    const Mesh::Halfedge_index h = mesh->halfedge(primitive.id());
    const Kernel::Triangle_3 triangle(mesh->point(mesh->source(h)), mesh->point(mesh->target(h)),
                                      mesh->point(mesh->target(mesh->next(h))));
    if (CGAL::squared_distance(centre, triangle) <= squared_radius) found = primitive.id();
  }

  template <class Node>
  bool do_intersect(const Point& centre, const Node& node) const {
    const CGAL::Bbox_3& box = node.bbox();
    double squared = 0;
    for (int a = 0; a < 3; ++a) {
      const double below = box.min(a) - centre[a], above = centre[a] - box.max(a);
      if (below > 0) squared += below * below;
      if (above > 0) squared += above * above;
    }
    return squared <= squared_radius;
  }
};

}  // namespace

struct SurfaceDistance::Impl {
  Mesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<SideOf> side;
};

SurfaceDistance::SurfaceDistance(const TriMesh& surface) : impl_(std::make_unique<Impl>()) {
  CHECK_GT(surface.triangles.rows(), 0) << "SurfaceDistance needs a non-empty surface";
  // Faces keep the input order (face index == triangle index). A layer's core surface can
  // pinch to a vertex shared by two fans (where the depth reaches through the part): such
  // vertices are split, which moves nothing. Anything else non-manifold is refused.
  try {
    impl_->mesh = ToSurfaceMesh<Point>(surface, "SurfaceDistance");
  } catch (const InputError&) {
    impl_->mesh = ToSurfaceMesh<Point>(SplitNonManifoldVertices(surface), "surface");
  }
  Mesh& mesh = impl_->mesh;
  impl_->tree = std::make_unique<Tree>(faces(mesh).first, faces(mesh).second, mesh);
  impl_->tree->build();
  impl_->tree->accelerate_distance_queries();  // built now, so queries are const/thread-safe
  impl_->side = std::make_unique<SideOf>(*impl_->tree);
}

SurfaceDistance::~SurfaceDistance() = default;
SurfaceDistance::SurfaceDistance(SurfaceDistance&&) noexcept = default;
SurfaceDistance& SurfaceDistance::operator=(SurfaceDistance&&) noexcept = default;

SurfaceDistance::Closest SurfaceDistance::Nearest(const Eigen::Vector3d& p) const {
  const Point query(p.x(), p.y(), p.z());
  const auto [point, face] = impl_->tree->closest_point_and_primitive(query);
  Closest closest;
  closest.point = Eigen::Vector3d(point.x(), point.y(), point.z());
  closest.triangle = static_cast<int>(face.idx());
  closest.distance = (closest.point - p).norm();
  return closest;
}

std::optional<SurfaceDistance::Closest> SurfaceDistance::NearestWithin(const Eigen::Vector3d& p,
                                                                       double radius) const {
  const Point query(p.x(), p.y(), p.z());
  BallQuery ball{&impl_->mesh, radius * radius};
  impl_->tree->traversal(query, ball);
  if (ball.found == Mesh::null_face()) return std::nullopt;
  // A corner of the face found is a point of the surface within radius + its size: a good
  // start that keeps the closest-point search local.
  const Mesh& mesh = impl_->mesh;
  const Mesh::Vertex_index corner = mesh.target(mesh.halfedge(ball.found));
  const auto [point, nearest] = impl_->tree->closest_point_and_primitive(
      query, std::make_pair(mesh.point(corner), ball.found));
  Closest closest;
  closest.point = Eigen::Vector3d(point.x(), point.y(), point.z());
  closest.triangle = static_cast<int>(nearest.idx());
  closest.distance = (closest.point - p).norm();
  if (closest.distance > radius) return std::nullopt;
  return closest;
}

bool SurfaceDistance::Inside(const Eigen::Vector3d& p) const {
  return (*impl_->side)(Point(p.x(), p.y(), p.z())) == CGAL::ON_BOUNDED_SIDE;
}

double SurfaceDistance::Signed(const Eigen::Vector3d& p, Closest* closest) const {
  const Closest nearest = Nearest(p);
  if (closest != nullptr) *closest = nearest;
  return Inside(p) ? -nearest.distance : nearest.distance;
}

}  // namespace ergo
