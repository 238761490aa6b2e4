// The shoe sole's body part (paper §5.2 scans a foot): an adult right foot — heel, arch,
// ball, five toes and the ankle — as a smooth union of ellipsoids and tapered limbs, with a
// plantar tissue layer 1–2 cm deep (heel pad deepest) that thins to a few millimetres over
// the top of the foot; the toes are all tissue. Frame: y up, the foot along +z (heel at the
// back), the big toe on the +x (medial) side, the heel's lowest point at y = 0 and the foot
// centred on z = 0. Metres, Pa, kg.
#pragma once

#include "problems/implicit_body.h"

namespace ergo {

struct FootOptions {
  double length = 0.26;  // heel to the tip of the longest toe, m (adults: 0.23–0.29)
  // Scale of the foot's breadth and height relative to a 0.26 m foot (breadth at the ball
  // 0.10 m).
  double breadth_scale = 1.0;
  // Plantar (sole-side) tissue depth by region, m: the heel pad is 1.5–2 cm, the ball ~1.3 cm.
  double heel_depth = 0.018, arch_depth = 0.010, ball_depth = 0.013;
  // Depth over the top and sides of the foot and the ankle, m (≥ half the edge length).
  double dorsal_depth = 0.006;
  // Young's modulus by region, Pa. Plantar tissue under standing loads is far stiffer than
  // the seated buttock tissue of the paper's 5–15 kPa (in-vivo heel-pad moduli are of the
  // order of 1e5 Pa): with 10 kPa the heel pad of this foot was crushed (the core sank 18 mm
  // into an 18 mm pad under half the body weight) and the equilibrium did not converge.
  double heel_modulus = 80e3, arch_modulus = 40e3, ball_modulus = 60e3, toe_modulus = 40e3,
         dorsal_modulus = 40e3;
  double poisson_ratio = 0.45;
  double total_mass = 1.4;  // kg: the foot and ankle (~1.4 % of 75 kg, plus the ankle)
  double blend_radius = 0.01;
  double region_width = 0.02;
};

// The implicit description (regions: heel, arch, ball, toes, ankle).
ImplicitBodySpec MakeFootSpec(const FootOptions& options);

}  // namespace ergo
