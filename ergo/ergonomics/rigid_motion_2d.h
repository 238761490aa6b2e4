// A rigid motion of the plane q ↦ R(θ) q + t: how a measured pressure map (a plate's grid, a
// sensor map) is placed on the support's plane (x, z) seen along the load, y up. θ in radians,
// counter-clockwise from +x towards +z; t in metres. Used by the map alignment and by the
// synthetic measurements that apply a known motion.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace ergo {

struct RigidMotion2d {
  double angle = 0;                                       // θ, radians
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // t, m

  Eigen::Matrix2d Rotation() const {
    const double c = std::cos(angle), s = std::sin(angle);
    Eigen::Matrix2d r;
    r << c, -s, s, c;
    return r;
  }
  Eigen::Vector2d Apply(const Eigen::Vector2d& q) const { return Rotation() * q + translation; }
  // The motion that undoes this one.
  RigidMotion2d Inverse() const {
    RigidMotion2d inverse;
    inverse.angle = -angle;
    inverse.translation = -(inverse.Rotation() * translation);
    return inverse;
  }
  // This motion after `first`: q ↦ this(first(q)).
  RigidMotion2d After(const RigidMotion2d& first) const {
    RigidMotion2d composed;
    composed.angle = angle + first.angle;
    composed.translation = Rotation() * first.translation + translation;
    return composed;
  }
  // The rotation by θ about `centre` followed by the shift `shift`.
  static RigidMotion2d About(const Eigen::Vector2d& centre, double angle,
                             const Eigen::Vector2d& shift) {
    RigidMotion2d motion;
    motion.angle = angle;
    motion.translation = centre - motion.Rotation() * centre + shift;
    return motion;
  }
};

}  // namespace ergo
