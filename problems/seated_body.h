// The chair's body part (paper §5.1 scans a person's lower back, buttocks and thighs): a
// seated adult's pelvis, buttocks, thighs and lower back as a smooth union of ellipsoids and
// tapered limbs, with a tissue layer whose depth and Young's modulus vary by region. Frame:
// y up, +z forward (towards the knees), x lateral; the buttocks' lowest point at y = 0 and
// the midline at x = 0. Metres, Pa, kg.
#pragma once

#include "problems/implicit_body.h"

namespace ergo {

struct SeatedBodyOptions {
  // Overall breadth across the buttocks (adults: about 0.35–0.40 m seated), m.
  double hip_breadth = 0.38;
  // Back of the buttocks to the front of the thighs' ends (near the knees; the standard
  // buttock–knee length is about 0.57–0.60 m to the front of the knee), m.
  double buttock_knee_length = 0.53;
  // z of the back of the buttocks, m (places the body on the seat).
  double back_z = -0.22;
  // Tissue depth below the skin by region, m (paper: measured; buttocks deepest).
  double buttock_depth = 0.045, thigh_depth = 0.03, back_depth = 0.022, pelvis_depth = 0.04;
  // Young's modulus by region, Pa (paper: 5–15 kPa; buttocks softest, back stiffest).
  double buttock_modulus = 6e3, thigh_modulus = 9e3, back_modulus = 13e3, pelvis_modulus = 8e3;
  double poisson_ratio = 0.45;
  // Total mass of the part, kg (a seated adult's buttocks + thighs + lower back: ~25–35 kg;
  // the core mass makes up the difference to the tissue's).
  double total_mass = 30;
  double blend_radius = 0.04;  // smooth-union radius of the creases, m
  double region_width = 0.04;  // width of the transitions between regions' depth and E, m
};

// The implicit description (regions: buttocks, thighs, lower back, pelvis).
ImplicitBodySpec MakeSeatedBodySpec(const SeatedBodyOptions& options);

}  // namespace ergo
