#include "ergo/body/body_state.h"

#include <cmath>

#include <Eigen/Geometry>

namespace ergo {

BodyState RestState(const LayeredBody& body) {
  BodyState state;
  state.free_displacement = Eigen::VectorXd::Zero(3 * body.free_vertices().size());
  state.centre = body.core_centre();
  return state;
}

BodyState TranslatedRestState(const LayeredBody& body, const Eigen::Vector3d& offset) {
  BodyState state = RestState(body);
  for (Eigen::Index i = 0; i < body.free_vertices().size(); ++i)
    state.free_displacement.segment<3>(3 * i) = offset;
  state.centre += offset;
  return state;
}

Vertices DeformedPositions(const LayeredBody& body, const BodyState& state) {
  const Vertices& rest = body.rest().vertices;
  Vertices positions(rest.rows(), 3);
  const Eigen::VectorXi& free = body.free_vertices();
  for (Eigen::Index i = 0; i < free.size(); ++i)
    positions.row(free[i]) =
        rest.row(free[i]) + state.free_displacement.segment<3>(3 * i).transpose();
  for (Eigen::Index a : body.attached_vertices()) {
    positions.row(a) =
        (state.centre + state.rotation * (rest.row(a).transpose() - body.core_centre()))
            .transpose();
  }
  return positions;
}

Eigen::Matrix3d RotationExp(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle < 1e-12) {
    Eigen::Matrix3d skew;
    skew << 0, -theta.z(), theta.y(), theta.z(), 0, -theta.x(), -theta.y(), theta.x(), 0;
    return Eigen::Matrix3d::Identity() + skew + 0.5 * skew * skew;
  }
  return Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix();
}

}  // namespace ergo
