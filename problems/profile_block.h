// The block supports of the chair and the shoe sole (paper §3.2: "a 0.5 m × 0.2 m × 0.5 m
// cube, which we beveled into a round arc in the knee region"; a flat sole): a box whose
// front top edge (towards +z) may be rounded into a quarter-circle arc, meshed finely on the
// top surface (which is designed) and coarsely on the walls and bottom. Closed, outward,
// metres; y is up.
#pragma once

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct ProfileBlock {
  double width = 0.5;                     // x extent, centred on x = 0, m
  double back_z = -0.25, front_z = 0.25;  // z extent, m
  double bottom_y = -0.2, top_y = 0;      // y extent, m
  // Radius of the arc replacing the front top edge (0 = a square edge), m; below both the
  // height and the depth of the block.
  double front_radius = 0.06;
  double top_spacing = 0.01;   // edge length on the top surface (flat part and arc), m
  double wall_spacing = 0.04;  // edge length on the walls and the bottom, m (≥ top_spacing)
};

// The block's surface. The top (flat part and arc) is a structured grid of about
// top_spacing; the front, back and bottom strips keep the top's x spacing; the two side caps
// grade from the top's spacing to the walls'. Throws InputError for impossible dimensions.
TriMesh MakeProfileBlock(const ProfileBlock& block);

// True for points of the designed top surface (flat part and arc), false on the side caps,
// the back wall, the bottom and the vertical front wall (within `tolerance` metres of those
// planes). The rule also holds for blocks that were edited later (a negative image carved
// into the top).
bool OnProfileBlockTop(const ProfileBlock& block, const Eigen::Vector3d& p,
                       double tolerance = 1e-7);

}  // namespace ergo
