// The mouse's body part (paper §5.3 poses a purchased hand mesh "so that it sits on the mouse
// in a natural configuration"): an adult right hand, relaxed over a mouse — a tilted palm
// resting on the mouse's back, four fingers of three phalanges each curled forward over its
// front until they rest on it, and the thumb down its +x side — as a smooth union of an
// ellipsoid and tapered limbs. The pose is computed against the mouse's balls, so the hand
// rests on them with a small clearance. Frame: y up, fingers towards +z, thumb towards +x.
// Metres, Pa, kg.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "problems/implicit_body.h"

namespace ergo {

// A ball of the shape the hand is posed on.
struct Ball {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.03;  // m
};

struct HandOptions {
  // Palm (an ellipsoid): breadth across the knuckles, length wrist to knuckles, thickness, m.
  double palm_breadth = 0.084, palm_length = 0.095, palm_thickness = 0.028;
  double palm_tilt = 0.2;         // palm pitched front-down by this angle, rad
  double palm_centre_z = -0.035;  // z of the palm's centre, m (over the mouse's back)
  double finger_scale = 1.0;      // scales finger lengths (index 85 mm to the tip's centre)
  // Tissue depth, m: under the palm (the palmar pads ~1 cm), over its back, fingers, thumb.
  double palm_depth = 0.010, dorsal_depth = 0.005, finger_depth = 0.004, thumb_depth = 0.005;
  // Young's modulus by region, Pa (paper: 5–15 kPa).
  double palm_modulus = 8e3, finger_modulus = 12e3, thumb_modulus = 10e3;
  double poisson_ratio = 0.45;
  // Total mass, kg: an adult hand is ~0.6 % of 75 kg ≈ 0.45 kg; the core makes up the rest.
  double total_mass = 0.45;
  double clearance = 5e-4;  // gap left between the posed hand and the balls, m
  double blend_radius = 0.008, region_width = 0.01;
};

// The implicit description (regions: palm, fingers, thumb), posed on the union of `balls`.
// Throws InputError when the hand cannot be posed (no ball under the palm).
ImplicitBodySpec MakeHandSpec(const HandOptions& options, const std::vector<Ball>& balls);

}  // namespace ergo
