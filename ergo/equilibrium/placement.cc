#include "ergo/equilibrium/placement.h"

#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {
namespace {

Vertices SkinPositions(const LayeredBody& body, const BodyState& state) {
  const Vertices positions = DeformedPositions(body, state);
  Vertices skin(body.skin().vertices.size(), 3);
  for (Eigen::Index i = 0; i < skin.rows(); ++i)
    skin.row(i) = positions.row(body.skin().vertices[i]);
  return skin;
}

bool AnyInside(const Vertices& points, const Eigen::Vector3d& offset, const Support& support) {
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (support.Contains(points.row(i).transpose() + offset)) return true;
  return false;
}

// Smallest distance from the translated points to the support surface.
double MinDistance(const Vertices& points, const Eigen::Vector3d& offset, const Support& support) {
  double nearest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    nearest = std::min(
        nearest,
        std::sqrt(support.ClosestPoint(points.row(i).transpose() + offset).squared_distance));
  return nearest;
}

}  // namespace

PlacementResult PlaceAboveSupport(const LayeredBody& body, const BodyState& state,
                                  const Support& support, double gap) {
  CHECK_GE(gap, 0.0);
  PlacementResult result;
  result.state = state;
  const Eigen::Vector3d load = body.TotalLoad();
  if (load.norm() == 0) return result;
  const Eigen::Vector3d down = load.normalized();
  const Vertices skin = SkinPositions(body, state);
  const double size = (skin.colwise().maxCoeff() - skin.colwise().minCoeff()).norm();
  const Vertices& s = support.mesh().vertices;
  const double support_size = (s.colwise().maxCoeff() - s.colwise().minCoeff()).norm();

  // Lift out of any initial penetration, one body size at a time.
  double t = 0;
  for (int lift = 0; AnyInside(skin, t * down, support); ++lift) {
    if (lift == 10) return result;  // the support surrounds the body: leave it alone
    t -= size;
  }
  // Sphere tracing along the load: no skin vertex can reach the support while the body
  // moves less than their smallest distance, so each step is safe and none tunnels.
  const double stop = 1e-7 * size;
  const double limit =
      t + 2 * (size + support_size) + std::abs((s * down).maxCoeff() - (skin * down).minCoeff());
  for (int step = 0; step < 1000 && t < limit; ++step) {
    const double distance = MinDistance(skin, t * down, support);
    if (distance <= stop) {
      result.state.centre += (t - gap) * down;
      for (Eigen::Index i = 0; i < body.free_vertices().size(); ++i)
        result.state.free_displacement.segment<3>(3 * i) += (t - gap) * down;
      result.moved = t - gap;
      result.found = true;
      return result;
    }
    t += distance;
  }
  return result;  // passed beside or beyond the support without touching it
}

}  // namespace ergo
