// Support: the closed surface S a body rests on (paper §3.5). A validated, closed and
// outward-oriented triangle mesh with an AABB tree over its triangles, answering "closest
// point of S to p, in which Voronoi feature (vertex / edge / face), and is p inside S?" —
// the anchor π_S(p) of Eq. 10. Units: metres.
//
// Const queries are safe from several threads at once (the tree is built eagerly and never
// modified by a query). UpdateVertices is not: do not query while updating.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "ergo/contact/feature.h"
#include "ergo/contact/point_feature_energy.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// The closest point of S to a query p.
struct SupportPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // π_S(p), the anchor on S, metres
  double squared_distance = 0.0;                    // ‖p − π_S(p)‖², m²
  Feature feature;      // the Voronoi feature of S holding π_S(p) (support vertex ids)
  int triangle = -1;    // the triangle that reported it (seeds the next query as a hint)
  bool inside = false;  // p strictly inside S; a point on S is outside
  Eigen::Vector3d query = Eigen::Vector3d::Zero();  // p itself
  // Which support shape answered (changes with every UpdateVertices): a hint from the same
  // shape also proves that a point within its distance of `query` is on the same side.
  std::uint64_t shape = 0;
};

class Support {
 public:
  // Validates `mesh` (ValidateSupportMesh: closed, manifold, outward, no degenerate
  // triangles) and builds the tree; throws InputError naming `source` otherwise.
  explicit Support(TriMesh mesh, const std::string& source = "support mesh");
  ~Support();
  // A copy of an already validated support: the same shape with its own tree (no
  // re-validation). Copies may be queried and updated independently.
  Support(const Support& other);
  Support& operator=(const Support&) = delete;
  Support(Support&&) noexcept;
  Support& operator=(Support&&) noexcept;

  const TriMesh& mesh() const;
  // Barycentric area of every vertex (a third of each incident triangle's), m², at the
  // current shape.
  const Eigen::VectorXd& vertex_areas() const;
  // Keeps vertex_areas() at the current shape through later UpdateVertices: a soft support's
  // contact quadrature is then over its rest areas (Lagrangian, like the skin's), so the
  // springs' stiffness does not vary with its deformation.
  void PinVertexAreas();
  // Identifies the current shape: changes with every UpdateVertices (as SupportPoint::shape).
  std::uint64_t shape() const;
  // True iff p lies strictly inside the axis-aligned bounding box of S: a point outside it
  // is outside S, with no search.
  bool InBoundingBox(const Eigen::Vector3d& p) const;

  // Moves the vertices (same count and connectivity) and rebuilds the tree and normals.
  // The new shape is not re-validated (cost); triangles that become degenerate get a zero
  // normal and are never reported as faces.
  void UpdateVertices(const Vertices& positions);

  // Closest point of S to p (finite, CHECKed), its feature and side. `hint`: a previous
  // answer for a nearby point (the previous anchor); it only seeds the search, the answer is
  // the same without it up to exact distance ties between triangles.
  SupportPoint ClosestPoint(const Eigen::Vector3d& p, const SupportPoint* hint = nullptr) const;

  // True iff p is strictly inside S (points on S and non-finite points are outside). No
  // search if p is outside S's bounding box, or if `hint` answered a query q on this shape
  // and ‖p − q‖ < its distance (the ball around q holds no point of S: same side as q).
  bool Contains(const Eigen::Vector3d& p, const SupportPoint* hint = nullptr) const;

  // The closest point if p is strictly inside S (a contact), std::nullopt otherwise; the
  // same shortcuts as Contains for points that cannot be inside (DESIGN §6: a vertex that
  // moved less than its distance to S since it was outside needs no query). Keep the last
  // SupportPoint a vertex got as its hint; it stays valid until the support moves.
  std::optional<SupportPoint> Penetration(const Eigen::Vector3d& p,
                                          const SupportPoint* hint = nullptr) const;

  // Penetration for a point followed across queries (a skin vertex over Newton iterations
  // and line-search trials): `track` holds the last full answer for this point (default-
  // constructed before the first call) and is refreshed whenever a search runs, inside or
  // outside, so later calls skip the search while the point stays within its distance of
  // where it was last outside.
  std::optional<SupportPoint> TrackPenetration(const Eigen::Vector3d& p, SupportPoint* track) const;

  // Positions of `feature`'s vertices in Feature::vertices order, for point_feature_energy.h.
  FeaturePositions Positions(const Feature& feature) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ergo
