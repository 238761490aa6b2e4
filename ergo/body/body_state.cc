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

BodyState MovedRigidly(const LayeredBody& body, const BodyState& state,
                       const Eigen::Vector3d& translation, const Eigen::Vector3d& rotation) {
  const Eigen::Matrix3d turn = RotationExp(rotation);
  const Vertices positions = DeformedPositions(body, state);
  const Vertices& rest = body.rest().vertices;
  BodyState moved = state;
  const Eigen::VectorXi& free = body.free_vertices();
  for (Eigen::Index i = 0; i < free.size(); ++i) {
    const Eigen::Vector3d p = positions.row(free[i]).transpose();
    moved.free_displacement.segment<3>(3 * i) =
        state.centre + turn * (p - state.centre) + translation - rest.row(free[i]).transpose();
  }
  moved.centre = state.centre + translation;
  moved.rotation = turn * state.rotation;
  moved.torque_angle = state.torque_angle + rotation;
  return moved;
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
