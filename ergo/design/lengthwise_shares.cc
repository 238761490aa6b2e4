#include "ergo/design/lengthwise_shares.h"

#include <algorithm>

#include <glog/logging.h>

namespace ergo {

LengthwiseShares ComputeLengthwiseShares(const LayeredBody& body, const SurfaceContacts& contacts,
                                         const std::vector<double>& ends, bool from_min_z) {
  CHECK(!ends.empty() && ends.back() == 1.0 && std::is_sorted(ends.begin(), ends.end()))
      << "band ends must increase to 1";
  LengthwiseShares out;
  const Eigen::Vector3d load = body.TotalLoad();
  const Skin& skin = body.skin();
  if (!(load.norm() > 0) || contacts.skin_force.rows() != skin.vertices.size()) return out;
  const Eigen::Vector3d down = load.normalized();
  const Vertices& rest = body.rest().vertices;
  const double min_z = rest.col(2).minCoeff(), extent = rest.col(2).maxCoeff() - min_z;
  std::vector<double> force(ends.size(), 0.0);
  for (Eigen::Index l = 0; l < skin.vertices.size(); ++l) {
    const double w = -contacts.skin_force.row(l).dot(down.transpose());
    if (!(w > 0)) continue;  // only what presses on the support
    double s = extent > 0 ? (rest(skin.vertices[l], 2) - min_z) / extent : 0;
    if (!from_min_z) s = 1 - s;
    // The first band whose end lies beyond s; the last one takes s = 1.
    const auto band = std::upper_bound(ends.begin(), ends.end() - 1, s) - ends.begin();
    force[band] += w;
    out.normal_force += w;
  }
  if (!(out.normal_force > 0)) return out;
  for (double f : force) out.shares.push_back(f / out.normal_force);
  return out;
}

}  // namespace ergo
