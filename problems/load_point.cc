#include "problems/load_point.h"

#include <Eigen/Geometry>

#include "ergo/mesh/input_error.h"

namespace ergo {

Eigen::Vector3d RestCentreOfMass(const LayeredBody& body) {
  const Vertices& rest = body.rest().vertices;
  Eigen::Vector3d moment = body.core_mass() * body.core_centre();
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    moment += body.vertex_mass()[i] * rest.row(i).transpose();
  return moment / body.total_mass();
}

Eigen::Vector3d LoadPointTorque(const LayeredBody& body, const Eigen::Vector3d& force,
                                double fraction, HeelEnd heel_end, const std::string& source) {
  if (!(fraction >= 0 && fraction <= 1)) {
    throw InputError(source, "", "the load point must be a fraction of the length in [0, 1]",
                     "e.g. 0.445 (quiet standing)");
  }
  const Vertices& rest = body.rest().vertices;
  const bool heel_at_min = HeelAtMinZ(rest, heel_end, source);
  const double min_z = rest.col(2).minCoeff(), max_z = rest.col(2).maxCoeff();
  Eigen::Vector3d point = body.core_centre();
  point.z() = heel_at_min ? min_z + fraction * (max_z - min_z) : max_z - fraction * (max_z - min_z);
  return TorqueThroughPoint(body, force, point);
}

Eigen::Vector3d TorqueThroughPoint(const LayeredBody& body, const Eigen::Vector3d& force,
                                   const Eigen::Vector3d& point) {
  const Eigen::Vector3d& centre = body.core_centre();
  const Eigen::Vector3d weight = body.total_mass() * body.gravity();
  return (point - centre).cross(force + weight) - (RestCentreOfMass(body) - centre).cross(weight);
}

}  // namespace ergo
