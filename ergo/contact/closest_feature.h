// Closest point of one triangle to a query point and which of the triangle's 7 Voronoi
// regions holds it (3 vertices, 3 edges, the face interior; paper Appendix A). The region
// decides the sliding-anchor formula (point_feature_energy.h). Units: metres.
#pragma once

#include <Eigen/Core>

#include "ergo/contact/feature.h"

namespace ergo {

// A triangle (twice its area) / (longest edge)² at or below this is a sliver: its normal is
// unreliable, so no query is ever classified into its face region (the closest edge or
// vertex is used instead; the distance then errs by at most the sliver's height).
inline constexpr double kSliverRatio = 1e-8;
// An edge no longer than this × the triangle's longest edge is degenerate: its line is
// unreliable, so its region is reported as its first vertex.
inline constexpr double kShortEdgeRatio = 1e-8;
// Slack, in barycentric coordinate / edge parameter, by which the face region and the edge
// regions are widened towards their lower-dimensional neighbours (covers rounding).
inline constexpr double kRegionTolerance = 1e-12;

// The closest point of triangle (x0, x1, x2) to a query and its region. Local numbering:
// vertex i is x_i; edge i joins x_i and x_{(i+1) mod 3}.
struct TriangleProjection {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // closest point on the triangle
  double squared_distance = 0.0;                    // ‖query − point‖², m²
  FeatureType type = FeatureType::kFace;
  int index = 0;  // local vertex (kVertex) or edge (kEdge) number; 0 for kFace
};

// Closest point of the triangle to p and its Voronoi region. Ties go to the higher-
// dimensional feature: the face region is closed (all barycentric coordinates of the
// projection ≥ −kRegionTolerance) and each edge region closed towards its vertices
// (parameter in [−kRegionTolerance, 1 + kRegionTolerance]). So over an edge between coplanar
// triangles, or a vertex inside a flat patch — features whose own regions have zero
// thickness — the plane formula is used, the one-sided limit from every side, not a spurious
// tangential spring; likewise the line formula along a straight crease. Among equally near
// edge candidates the first in the order edge 0, 1, 2 wins. Slivers (kSliverRatio) never
// report kFace, degenerate edges (kShortEdgeRatio) never kEdge; the result is finite for
// finite input.
TriangleProjection ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& x0,
                                          const Eigen::Vector3d& x1, const Eigen::Vector3d& x2);

}  // namespace ergo
