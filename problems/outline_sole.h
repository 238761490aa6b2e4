// A fitted insole (issue 14): a flat-bottomed slab whose outline follows the foot's footprint
// grown by a margin, instead of a rectangle around it. The footprint is the foot's skin below
// a height above its lowest point, projected on the ground (x, z), rasterised, closed
// morphologically (gaps between the toes and along the arch are bridged), grown by the
// margin and traced; the top is a Delaunay mesh of that outline with edges of about
// `top_spacing` (the designed surface), the walls and the flat bottom coarser. Closed,
// outward, metres; y up, the top at `top_y`.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct OutlineSoleOptions {
  double margin = 0.01;            // outline beyond the footprint, m
  double footprint_height = 0.03;  // skin up to this height above its lowest point counts, m
  double thickness = 0.02;         // m
  double top_y = 0;                // m
  double top_spacing = 0.01;       // edge length on the top, m
  double wall_spacing = 0.01;      // edge length on the walls and bottom, m (≥ top_spacing)
  double raster = 0.002;           // footprint raster cell, m
};

struct OutlineSole {
  TriMesh mesh;
  std::vector<bool> top;     // per vertex: on the designed top (its outline included)
  Eigen::MatrixX2d outline;  // the traced outline (x, z), counter-clockwise seen from +y
};

// `foot`: the foot's skin at rest (y up). Throws InputError when the footprint is empty or
// the options are not positive.
OutlineSole MakeOutlineSole(const TriMesh& foot, const OutlineSoleOptions& options);

}  // namespace ergo
