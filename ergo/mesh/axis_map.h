// Scans come in their scanner's axes (the FIND foot: z up, length along x); ergo's scenes
// use y up with the part's length along z. An axis map names, for ergo's x, y and z in turn,
// the input axis it takes (with a sign): "y,z,x" makes the input's y ergo's x, the input's z
// ergo's y (up) and the input's x ergo's z. Only proper rotations are accepted (a mirror
// would turn a left foot into a right one and the surface inside out).
#pragma once

#include <string>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Parses "x,y,z", "y,z,x", "-x,z,y", ... into the rotation R with ergo = R · input. Throws
// InputError naming `flag` for anything else (an unknown axis, a repeated axis, a mirror).
Eigen::Matrix3d ParseAxisMap(const std::string& text, const std::string& flag);

// Rotates every row of `points` (#P x 3) by R.
void ApplyAxisMap(const Eigen::Matrix3d& rotation, Vertices* points);

}  // namespace ergo
