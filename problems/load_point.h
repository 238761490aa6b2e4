// A load a user can state: where the body's weight line meets the support. The external
// force on the core (half the wearer's weight for the shoe) acts at the core's centre; a
// torque τ on the core moves the line of action of the whole load (that force plus the
// part's own weight) through the point P at a fraction of the part's length from its heel
// (or back) end. On a flat, frictionless support the centre of pressure is then P.
// SI units; y up, the length along z.
#pragma once

#include <string>

#include <Eigen/Core>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/layered_body.h"

namespace ergo {

// τ = (P − C) × (F + M g) − (G − C) × M g, with C the core's centre, G the part's centre of
// mass at rest, M its mass, F `force`, and P at `fraction` ∈ [0, 1] of the rest extent along
// z from the heel end (`heel_end`; HeelAtMinZ decides kAuto), at C's x and y. Throws
// InputError naming `source` for a fraction outside [0, 1].
Eigen::Vector3d LoadPointTorque(const LayeredBody& body, const Eigen::Vector3d& force,
                                double fraction, HeelEnd heel_end, const std::string& source);

// The same for a point given directly (its x and z are used; y is irrelevant for a vertical
// load): τ = (P − C) × (F + M g) − (G − C) × M g.
Eigen::Vector3d TorqueThroughPoint(const LayeredBody& body, const Eigen::Vector3d& force,
                                   const Eigen::Vector3d& point);

// The part's centre of mass at rest, m.
Eigen::Vector3d RestCentreOfMass(const LayeredBody& body);

}  // namespace ergo
