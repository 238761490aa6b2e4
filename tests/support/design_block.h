// The small block the design-space tests move: 8 cm x 10 cm, top spacing 1 cm, with a 2 cm
// rounded front edge, so its designed top has a flat part and a curved one.
#pragma once

#include "problems/profile_block.h"

namespace ergo::testing {

inline ProfileBlock SmallDesignBlock() {
  ProfileBlock shape;
  shape.width = 0.08;
  shape.back_z = -0.05;
  shape.front_z = 0.05;
  shape.bottom_y = -0.04;
  shape.front_radius = 0.02;
  shape.top_spacing = 0.01;
  shape.wall_spacing = 0.02;
  return shape;
}

}  // namespace ergo::testing
