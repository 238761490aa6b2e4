#include "ergo/design/centre_of_pressure.h"

namespace ergo {

CentreOfPressure ComputeCentreOfPressure(const LayeredBody& body, const BodyState& state,
                                         const SurfaceContacts& contacts) {
  CentreOfPressure cop;
  const Eigen::Vector3d load = body.TotalLoad();
  if (!(load.norm() > 0) || contacts.skin_force.rows() != body.skin().vertices.size()) return cop;
  const Eigen::Vector3d down = load.normalized();
  const Vertices positions = DeformedPositions(body, state);
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (Eigen::Index l = 0; l < body.skin().vertices.size(); ++l) {
    const double w = -contacts.skin_force.row(l).dot(down.transpose());
    if (w == 0) continue;
    moment += w * positions.row(body.skin().vertices[l]).transpose();
    cop.normal_force += w;
  }
  if (!(cop.normal_force > 0)) {
    cop.normal_force = 0;
    return cop;
  }
  cop.point = moment / cop.normal_force;
  const Vertices& rest = body.rest().vertices;
  const double min_z = rest.col(2).minCoeff(), extent = rest.col(2).maxCoeff() - min_z;
  cop.z_fraction = extent > 0 ? (cop.point.z() - min_z) / extent : 0;
  return cop;
}

}  // namespace ergo
