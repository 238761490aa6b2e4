// The centre of pressure of an equilibrium: where the resultant of the contact forces on the
// skin meets the support, the point a pressure plate reports. With the load direction d
// (gravity plus the external force), each skin vertex's contact force f_i counts by its
// component along −d, w_i = −f_i·d̂, and CoP = Σ w_i x_i / Σ w_i over the deformed skin
// positions x_i. Metres, N.
#pragma once

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/contact/surface_contact.h"

namespace ergo {

struct CentreOfPressure {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m
  double normal_force = 0;                          // Σ w_i, N (0: no contact, `point` undefined)
  // (point.z − the body's smallest rest z) / its rest extent along z: for the shoe, the
  // fraction of the foot's length from the heel (the generated foot's heel is at min z).
  double z_fraction = 0;
};

CentreOfPressure ComputeCentreOfPressure(const LayeredBody& body, const BodyState& state,
                                         const SurfaceContacts& contacts);

}  // namespace ergo
