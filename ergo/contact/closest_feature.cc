#include "ergo/contact/closest_feature.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

namespace ergo {

TriangleProjection ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& x0,
                                          const Eigen::Vector3d& x1, const Eigen::Vector3d& x2) {
  const Eigen::Vector3d* x[3] = {&x0, &x1, &x2};
  const Eigen::Vector3d edge[3] = {x1 - x0, x2 - x1, x0 - x2};
  const double length2[3] = {edge[0].squaredNorm(), edge[1].squaredNorm(), edge[2].squaredNorm()};
  const double longest2 = std::max({length2[0], length2[1], length2[2]});

  const Eigen::Vector3d offset[3] = {p - x0, p - x1, p - x2};  // p − x_i

  TriangleProjection result;
  const Eigen::Vector3d normal = edge[0].cross(x2 - x0);
  const double h = normal.squaredNorm();
  // Which edges p projects outside of (all three for a sliver, whose normal is unreliable):
  // only those can hold the closest boundary point of a convex polygon.
  bool outside[3] = {true, true, true};
  if (h > kSliverRatio * kSliverRatio * longest2 * longest2) {
    // The signed areas normal·(edge_i × (p − x_i)) are h × the barycentric coordinates of
    // the projection; the face region is closed, with kRegionTolerance of slack.
    double area[3];
    for (int i = 0; i < 3; ++i) {
      area[i] = normal.dot(edge[i].cross(offset[i]));
      outside[i] = area[i] < 0;
    }
    const double slack = -kRegionTolerance * h;
    if (area[0] >= slack && area[1] >= slack && area[2] >= slack) {
      const double g = normal.dot(offset[0]);
      result.point = p - (g / h) * normal;
      result.squared_distance = g * g / h;
      result.type = FeatureType::kFace;
      result.index = 0;
      return result;
    }
  }

  // Outside the face region (or a sliver): the nearest of the candidate segments, each
  // closed towards its vertices with kRegionTolerance of slack on its parameter.
  result.squared_distance = std::numeric_limits<double>::infinity();
  const double short2 = kShortEdgeRatio * kShortEdgeRatio * longest2;
  for (int i = 0; i < 3; ++i) {
    if (!outside[i]) continue;
    const int j = (i + 1) % 3;
    Eigen::Vector3d q;
    FeatureType type;
    int index;
    const double t = length2[i] > short2 ? offset[i].dot(edge[i]) / length2[i] : 0.0;
    if (length2[i] <= short2 || t < -kRegionTolerance) {
      q = *x[i], type = FeatureType::kVertex, index = i;
    } else if (t > 1 + kRegionTolerance) {
      q = *x[j], type = FeatureType::kVertex, index = j;
    } else {
      q = *x[i] + t * edge[i], type = FeatureType::kEdge, index = i;
    }
    const double d2 = (p - q).squaredNorm();
    if (d2 < result.squared_distance) {
      result.point = q;
      result.squared_distance = d2;
      result.type = type;
      result.index = index;
    }
  }
  return result;
}

}  // namespace ergo
