// Small layered bodies for the body-stage tests: a hollow cube (a 3x3x3 tet grid with its
// central cell removed; the cavity's vertices are attached to a core filling it).
#pragma once

#include "ergo/body/layered_body.h"

namespace ergo::testing {

// Side `size` metres, centred at `centre`, cells^3 grid with the middle (cells/3)^3 block
// hollowed out (cells must be a multiple of 3), turned by `orientation` about its centre.
// Uniform E and ν.
LayeredBody MakeHollowCubeBody(double size, int cells, double youngs_modulus, double poisson_ratio,
                               const LayeredBodyOptions& options,
                               const Eigen::Vector3d& centre = Eigen::Vector3d::Zero(),
                               const Eigen::Matrix3d& orientation = Eigen::Matrix3d::Identity());

}  // namespace ergo::testing
