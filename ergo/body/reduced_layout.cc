#include "ergo/body/reduced_layout.h"

#include <glog/logging.h>
#include <Eigen/Geometry>

namespace ergo {

ReducedLayout::ReducedLayout(const LayeredBody& body, Eigen::Index support_size)
    : core_offset_(3 * body.free_vertices().size()),
      core_components_(body.lock().FreeComponents()),
      support_size_(support_size) {
  CHECK_GE(support_size, 0);
  CHECK_EQ(support_size % 3, 0);
}

Eigen::MatrixXd ReducedLayout::CoreJacobian(const Eigen::Vector3d& h) const {
  // Full B = [I  −[h]×]: ∂p/∂c = I, ∂p/∂θ = −[h]× (δθ × h = −h × δθ).
  Eigen::Matrix<double, 3, 6> full;
  full.leftCols<3>().setIdentity();
  full.rightCols<3>() << 0, h.z(), -h.y(), -h.z(), 0, h.x(), h.y(), -h.x(), 0;
  Eigen::MatrixXd restricted(3, core_count());
  for (int j = 0; j < core_count(); ++j) restricted.col(j) = full.col(core_components_[j]);
  return restricted;
}

Eigen::VectorXd ReducedLayout::ReduceGradient(const LayeredBody& body, const BodyState& state,
                                              const Vertices& positions,
                                              const Vertices& vertex_gradient) const {
  Eigen::VectorXd reduced = Eigen::VectorXd::Zero(size());
  const Eigen::VectorXi& free = body.free_vertices();
  for (Eigen::Index i = 0; i < free.size(); ++i)
    reduced.segment<3>(3 * i) = vertex_gradient.row(free[i]).transpose();
  Eigen::Matrix<double, 6, 1> core = Eigen::Matrix<double, 6, 1>::Zero();
  for (Eigen::Index a : body.attached_vertices()) {
    const Eigen::Vector3d g = vertex_gradient.row(a).transpose();
    const Eigen::Vector3d h = positions.row(a).transpose() - state.centre;
    core.head<3>() += g;
    core.tail<3>() += h.cross(g);  // Bᵀ g rotation part: [h]× g
  }
  for (int j = 0; j < core_count(); ++j) reduced[core_offset_ + j] = core[core_components_[j]];
  return reduced;
}

BodyState ReducedLayout::Retract(const BodyState& state, const Eigen::VectorXd& step) const {
  CHECK_EQ(step.size(), size());
  BodyState next = state;
  next.free_displacement += step.head(core_offset_);
  Eigen::Vector3d translation = Eigen::Vector3d::Zero(), rotation = Eigen::Vector3d::Zero();
  for (int j = 0; j < core_count(); ++j) {
    const int component = core_components_[j];
    (component < 3 ? translation[component] : rotation[component - 3]) = step[core_offset_ + j];
  }
  next.centre += translation;
  next.rotation = RotationExp(rotation) * state.rotation;
  next.torque_angle += rotation;
  if (support_size_ > 0) {
    if (next.support_displacement.size() == 0)
      next.support_displacement = Eigen::VectorXd::Zero(support_size_);
    CHECK_EQ(next.support_displacement.size(), support_size_);
    next.support_displacement += step.tail(support_size_);
  }
  return next;
}

Vertices ReducedLayout::VertexVelocity(const LayeredBody& body, const BodyState& state,
                                       const Vertices& positions,
                                       const Eigen::VectorXd& step) const {
  CHECK_EQ(step.size(), size());
  Vertices velocity = Vertices::Zero(positions.rows(), 3);
  const Eigen::VectorXi& free = body.free_vertices();
  for (Eigen::Index i = 0; i < free.size(); ++i)
    velocity.row(free[i]) = step.segment<3>(3 * i).transpose();
  const Eigen::VectorXd core_step = step.segment(core_offset_, core_count());
  for (Eigen::Index a : body.attached_vertices()) {
    const Eigen::Vector3d h = positions.row(a).transpose() - state.centre;
    velocity.row(a) = (CoreJacobian(h) * core_step).transpose();
  }
  return velocity;
}

}  // namespace ergo
