// A flat structured triangle grid for filter and Laplacian tests: the square
// [−half_width, half_width]² of the xz plane at y = 0, cells x cells squares each cut along
// the same diagonal, normals +y. Grids with cells, 2·cells, 4·cells nest: every coarse vertex
// is a fine vertex, and the fine vertices lie on coarse edges or at coarse vertices.
#pragma once

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo::testing {

// Vertex (i, j) (i along x, j along z, 0..cells) has index j·(cells + 1) + i.
TriMesh MakeFlatGrid(double half_width, int cells);

// The piecewise-linear interpolant at (x, z) of per-vertex `values` on MakeFlatGrid(
// half_width, cells) (the same triangles), for comparing fields on grids of two resolutions.
double InterpolateOnFlatGrid(const Eigen::VectorXd& values, double half_width, int cells, double x,
                             double z);

}  // namespace ergo::testing
