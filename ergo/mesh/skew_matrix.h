// The cross-product matrix [v]×, with [v]× w = v × w.
#pragma once

#include <Eigen/Core>

namespace ergo {

inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace ergo
