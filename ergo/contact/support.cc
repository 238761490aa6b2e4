// The only translation unit that includes CGAL for contact: the AABB tree stays behind
// Support's pimpl so the rest of the project never compiles CGAL headers.
#include "ergo/contact/support.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <glog/logging.h>
#include <Eigen/Geometry>

#include "ergo/contact/closest_feature.h"
#include "ergo/contact/directed_edge_key.h"
#include "ergo/contact/support_validation.h"

namespace ergo {
namespace {

// DESIGN §6: distances need no exact predicates.
using Kernel = CGAL::Simple_cartesian<double>;

// One support triangle with its coordinates cached in the tree (no indirection per visit).
struct TriangleRecord {
  int id;
  std::array<int, 3> corner;  // support vertex ids
  std::array<Eigen::Vector3d, 3> x;
};

class TrianglePrimitive {
 public:
  using Id = int;
  using Point = Kernel::Point_3;
  using Datum = Kernel::Triangle_3;

  TrianglePrimitive() = default;
  explicit TrianglePrimitive(std::vector<TriangleRecord>::const_iterator it) : record_(*it) {}

  Id id() const { return record_.id; }
  Datum datum() const {
    return Datum(ToPoint(record_.x[0]), ToPoint(record_.x[1]), ToPoint(record_.x[2]));
  }
  // The centroid: the tree splits primitives by it.
  Point reference_point() const {
    return ToPoint((record_.x[0] + record_.x[1] + record_.x[2]) / 3);
  }
  const std::array<Eigen::Vector3d, 3>& x() const { return record_.x; }
  const std::array<int, 3>& corner() const { return record_.corner; }

 private:
  static Point ToPoint(const Eigen::Vector3d& v) { return Point(v.x(), v.y(), v.z()); }
  TriangleRecord record_;
};

using Traits = CGAL::AABB_traits<Kernel, TrianglePrimitive>;
using Tree = CGAL::AABB_tree<Traits>;
using Node = CGAL::AABB_node<Traits>;
// ClosestTriangleSearch::Descend follows AABB_node's layout of CGAL 5.5 (Debian 12); check
// it (the brute-force tests do) before moving to another CGAL release.
static_assert(CGAL_VERSION_NR >= 1050500000 && CGAL_VERSION_NR < 1050600000,
              "Support's tree descent is written for CGAL 5.5's AABB_node layout");

double SquaredDistanceToBox(const Eigen::Vector3d& p, const CGAL::Bbox_3& box) {
  const double gx = std::max(std::max(box.xmin() - p.x(), p.x() - box.xmax()), 0.0);
  const double gy = std::max(std::max(box.ymin() - p.y(), p.y() - box.ymax()), 0.0);
  const double gz = std::max(std::max(box.zmin() - p.z(), p.z() - box.zmax()), 0.0);
  return gx * gx + gy * gy + gz * gz;
}

// The nearest triangle to p among those offered. Ties between triangles go to the smaller
// triangle id, so the answer does not depend on the visiting order or on the hint (up to
// rounding in the box distances used for pruning).
class ClosestTriangleSearch {
 public:
  explicit ClosestTriangleSearch(const Eigen::Vector3d& p) : p_(p) {
    best_.squared_distance = std::numeric_limits<double>::infinity();
  }

  void Offer(const TrianglePrimitive& primitive) {
    const int id = primitive.id();
    if (id == best_id_) return;  // the hint, already offered
    const std::array<Eigen::Vector3d, 3>& x = primitive.x();
    // The triangle's own box is a cheap lower bound: skips ~40 % of the full tests.
    const Eigen::Vector3d lo = x[0].cwiseMin(x[1]).cwiseMin(x[2]);
    const Eigen::Vector3d hi = x[0].cwiseMax(x[1]).cwiseMax(x[2]);
    if ((lo - p_).cwiseMax(p_ - hi).cwiseMax(0.0).squaredNorm() > best_.squared_distance) return;
    const TriangleProjection candidate = ClosestPointOnTriangle(p_, x[0], x[1], x[2]);
    if (candidate.squared_distance < best_.squared_distance ||
        (candidate.squared_distance == best_.squared_distance && id < best_id_)) {
      best_ = candidate;
      best_id_ = id;
      best_primitive_ = &primitive;
    }
  }

  // Depth-first over the tree, nearer child box first, each box re-checked against the best
  // distance found so far just before it is entered. (CGAL's closest_point_and_primitive
  // visits in a fixed order and seeds itself from a k-d tree; its traversal_with_priority
  // enters the second child without re-checking it. Measured on the 30k-triangle benchmark
  // sphere: 66 box tests per cold query with traversal_with_priority, 44 with this.)
  // `count` is the number of primitives below `node`; the layout rules (2: two primitives,
  // 3: a primitive and a node of 2, n: nodes of n/2 and n − n/2) are AABB_node::traversal's.
  void Descend(const Node& node, std::size_t count) {
    switch (count) {
      case 2:
        Offer(node.left_data());
        Offer(node.right_data());
        return;
      case 3:
        Offer(node.left_data());
        if (SquaredDistanceToBox(p_, node.right_child().bbox()) <= best_.squared_distance) {
          Descend(node.right_child(), 2);
        }
        return;
      default: {
        const std::size_t left_count = count / 2, right_count = count - count / 2;
        const double left = SquaredDistanceToBox(p_, node.left_child().bbox());
        const double right = SquaredDistanceToBox(p_, node.right_child().bbox());
        if (left <= right) {
          if (left <= best_.squared_distance) Descend(node.left_child(), left_count);
          if (right <= best_.squared_distance) Descend(node.right_child(), right_count);
        } else {
          if (right <= best_.squared_distance) Descend(node.right_child(), right_count);
          if (left <= best_.squared_distance) Descend(node.left_child(), left_count);
        }
      }
    }
  }

  const TriangleProjection& best() const { return best_; }
  const TrianglePrimitive& best_primitive() const { return *best_primitive_; }

 private:
  Eigen::Vector3d p_;
  TriangleProjection best_;
  int best_id_ = std::numeric_limits<int>::max();
  const TrianglePrimitive* best_primitive_ = nullptr;
};

// Every Build gets a new stamp, so hints name the exact shape that produced them.
std::atomic<std::uint64_t> next_shape{1};

}  // namespace

struct Support::Impl {
  TriMesh mesh;
  Tree tree;
  CGAL::Bbox_3 box;
  std::vector<int> neighbour;                  // 3f + c -> triangle across edge c of f
  std::vector<Eigen::Vector3d> face_normal;    // unit (zero for a degenerate triangle)
  std::vector<Eigen::Vector3d> edge_normal;    // 3f + c: sum of the two unit face normals
  std::vector<Eigen::Vector3d> vertex_normal;  // angle-weighted sum (Bærentzen & Aanæs 2005)
  Eigen::VectorXd vertex_area;                 // barycentric, m²
  bool areas_pinned = false;                   // vertex_area kept from the shape PinVertexAreas saw
  std::uint64_t shape = 0;
  // Triangle id -> its primitive in the tree: the hint is read from the copy the descent
  // will touch anyway (one cache line instead of an index row plus three vertex rows).
  std::vector<const TrianglePrimitive*> primitive;

  Eigen::Vector3d X(int v) const { return mesh.vertices.row(v).transpose(); }

  void FindNeighbours() {
    const int nf = static_cast<int>(mesh.triangles.rows());
    std::unordered_map<std::uint64_t, int> directed;
    directed.reserve(3 * nf);
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 3; ++c)
        directed[DirectedEdgeKey(mesh.triangles(f, c), mesh.triangles(f, (c + 1) % 3))] = f;
    neighbour.assign(3 * nf, -1);
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 3; ++c)
        neighbour[3 * f + c] =
            directed.at(DirectedEdgeKey(mesh.triangles(f, (c + 1) % 3), mesh.triangles(f, c)));
  }

  // Tree and pseudo-normals for the current vertex positions.
  void Build() {
    shape = next_shape.fetch_add(1);
    const int nf = static_cast<int>(mesh.triangles.rows());
    std::vector<TriangleRecord> records(nf);
    for (int f = 0; f < nf; ++f) {
      records[f].id = f;
      for (int c = 0; c < 3; ++c) {
        records[f].corner[c] = mesh.triangles(f, c);
        records[f].x[c] = X(mesh.triangles(f, c));
      }
    }
    tree.rebuild(records.cbegin(), records.cend());  // clears, inserts, builds eagerly
    box = tree.bbox();
    primitive.assign(nf, nullptr);
    CollectPrimitives(*tree.root_node(), tree.size());

    face_normal.assign(nf, Eigen::Vector3d::Zero());
    if (!areas_pinned) vertex_area = Eigen::VectorXd::Zero(mesh.vertices.rows());
    for (int f = 0; f < nf; ++f) {
      const auto& x = records[f].x;
      const Eigen::Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
      const double length = n.norm();
      if (length > 0) face_normal[f] = n / length;
      if (!areas_pinned)
        for (int c = 0; c < 3; ++c) vertex_area[mesh.triangles(f, c)] += length / 6;
    }
    edge_normal.resize(3 * nf);
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 3; ++c)
        edge_normal[3 * f + c] = face_normal[f] + face_normal[neighbour[3 * f + c]];
    vertex_normal.assign(mesh.vertices.rows(), Eigen::Vector3d::Zero());
    for (int f = 0; f < nf; ++f) {
      const auto& x = records[f].x;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d a = x[(c + 1) % 3] - x[c], b = x[(c + 2) % 3] - x[c];
        const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
        vertex_normal[mesh.triangles(f, c)] += angle * face_normal[f];
      }
    }
  }

  void CollectPrimitives(const Node& node, std::size_t count) {
    switch (count) {
      case 2:
        primitive[node.left_data().id()] = &node.left_data();
        primitive[node.right_data().id()] = &node.right_data();
        return;
      case 3:
        primitive[node.left_data().id()] = &node.left_data();
        CollectPrimitives(node.right_child(), 2);
        return;
      default:
        CollectPrimitives(node.left_child(), count / 2);
        CollectPrimitives(node.right_child(), count - count / 2);
    }
  }

  SupportPoint Finish(const Eigen::Vector3d& p, const TriangleProjection& projection,
                      const TrianglePrimitive& primitive) const {
    const int triangle = primitive.id();
    SupportPoint result;
    result.query = p;
    result.shape = shape;
    result.point = projection.point;
    result.squared_distance = projection.squared_distance;
    result.triangle = triangle;
    const auto corner = [&](int c) { return primitive.corner()[c % 3]; };
    Eigen::Vector3d pseudo_normal = Eigen::Vector3d::Zero();
    switch (projection.type) {
      case FeatureType::kVertex:
        result.feature = Feature::Vertex(corner(projection.index));
        pseudo_normal = vertex_normal[corner(projection.index)];
        break;
      case FeatureType::kEdge:
        result.feature = Feature::Edge(corner(projection.index), corner(projection.index + 1));
        pseudo_normal = edge_normal[3 * triangle + projection.index];
        break;
      case FeatureType::kFace:
        result.feature = Feature::Face(corner(0), corner(1), corner(2));
        pseudo_normal = face_normal[triangle];
        break;
    }
    // Bærentzen & Aanæs: for a closed manifold, p is inside iff (p − π)·n < 0 with n the
    // angle-weighted pseudo-normal of the closest feature; 0 (p on S) counts as outside.
    result.inside = (p - projection.point).dot(pseudo_normal) < 0;
    return result;
  }

  bool StrictlyInsideBox(const Eigen::Vector3d& p) const {
    for (int axis = 0; axis < 3; ++axis)
      if (!(p[axis] > box.min(axis) && p[axis] < box.max(axis))) return false;
    return true;
  }

  // True if `hint` proves p is on its side of S without a search: it answered a query q on
  // this shape and p lies in the open ball around q of radius dist(q, S), which S does not
  // meet. The 1e-9 relative margin covers the rounding of the stored distance.
  bool SameSideAsHint(const Eigen::Vector3d& p, const SupportPoint* hint) const {
    return hint != nullptr && hint->shape == shape &&
           (p - hint->query).squaredNorm() < (1 - 1e-9) * hint->squared_distance;
  }
};

Support::Support(TriMesh mesh, const std::string& source) : impl_(std::make_unique<Impl>()) {
  ValidateSupportMesh(mesh, source);
  impl_->mesh = std::move(mesh);
  impl_->tree.do_not_accelerate_distance_queries();  // the descent needs no k-d tree
  impl_->FindNeighbours();
  impl_->Build();
}

Support::Support(const Support& other) : impl_(std::make_unique<Impl>()) {
  impl_->mesh = other.impl_->mesh;
  impl_->tree.do_not_accelerate_distance_queries();
  impl_->neighbour = other.impl_->neighbour;
  impl_->areas_pinned = other.impl_->areas_pinned;
  impl_->vertex_area = other.impl_->vertex_area;
  impl_->Build();
}

Support::~Support() = default;
Support::Support(Support&&) noexcept = default;
Support& Support::operator=(Support&&) noexcept = default;

const TriMesh& Support::mesh() const { return impl_->mesh; }
const Eigen::VectorXd& Support::vertex_areas() const { return impl_->vertex_area; }
void Support::PinVertexAreas() { impl_->areas_pinned = true; }
std::uint64_t Support::shape() const { return impl_->shape; }
bool Support::InBoundingBox(const Eigen::Vector3d& p) const { return impl_->StrictlyInsideBox(p); }

void Support::UpdateVertices(const Vertices& positions) {
  CHECK_EQ(positions.rows(), impl_->mesh.vertices.rows()) << "vertex count changed";
  CHECK(positions.allFinite()) << "non-finite support vertex position";
  impl_->mesh.vertices = positions;
  impl_->Build();
}

SupportPoint Support::ClosestPoint(const Eigen::Vector3d& p, const SupportPoint* hint) const {
  CHECK(p.allFinite()) << "closest point of a non-finite query " << p.transpose();
  ClosestTriangleSearch search(p);
  const int num_triangles = static_cast<int>(impl_->mesh.triangles.rows());
  if (hint != nullptr && hint->triangle >= 0 && hint->triangle < num_triangles) {
    search.Offer(*impl_->primitive[hint->triangle]);
  }
  search.Descend(*impl_->tree.root_node(), impl_->tree.size());
  return impl_->Finish(p, search.best(), search.best_primitive());
}

bool Support::Contains(const Eigen::Vector3d& p, const SupportPoint* hint) const {
  if (!impl_->StrictlyInsideBox(p)) return false;
  if (impl_->SameSideAsHint(p, hint)) return hint->inside;
  return ClosestPoint(p, hint).inside;
}

std::optional<SupportPoint> Support::Penetration(const Eigen::Vector3d& p,
                                                 const SupportPoint* hint) const {
  if (!impl_->StrictlyInsideBox(p)) return std::nullopt;
  if (impl_->SameSideAsHint(p, hint) && !hint->inside) return std::nullopt;
  SupportPoint result = ClosestPoint(p, hint);
  if (!result.inside) return std::nullopt;
  return result;
}

std::optional<SupportPoint> Support::TrackPenetration(const Eigen::Vector3d& p,
                                                      SupportPoint* track) const {
  CHECK(track != nullptr);
  if (!impl_->StrictlyInsideBox(p)) return std::nullopt;
  if (impl_->SameSideAsHint(p, track) && !track->inside) return std::nullopt;
  *track = ClosestPoint(p, track);
  if (!track->inside) return std::nullopt;
  return *track;
}

FeaturePositions Support::Positions(const Feature& feature) const {
  FeaturePositions x;
  for (int i = 0; i < 3; ++i)
    x[i] = i < feature.size() ? impl_->X(feature.vertices[i]) : Eigen::Vector3d::Zero();
  return x;
}

}  // namespace ergo
