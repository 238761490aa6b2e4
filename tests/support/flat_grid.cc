#include "tests/support/flat_grid.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

namespace ergo::testing {

TriMesh MakeFlatGrid(double half_width, int cells) {
  CHECK_GT(cells, 0);
  const int side = cells + 1;
  const double spacing = 2 * half_width / cells;
  TriMesh mesh;
  mesh.vertices.resize(side * side, 3);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      mesh.vertices.row(j * side + i) << -half_width + i * spacing, 0, -half_width + j * spacing;
  mesh.triangles.resize(2 * cells * cells, 3);
  int f = 0;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const int a = j * side + i, b = a + 1, c = a + side, d = c + 1;
      // Diagonal a–d; (a, c, d) and (a, d, b) are counter-clockwise seen from +y.
      mesh.triangles.row(f++) << a, c, d;
      mesh.triangles.row(f++) << a, d, b;
    }
  }
  return mesh;
}

double InterpolateOnFlatGrid(const Eigen::VectorXd& values, double half_width, int cells, double x,
                             double z) {
  const int side = cells + 1;
  CHECK_EQ(values.size(), side * side);
  const double spacing = 2 * half_width / cells;
  const double u = (x + half_width) / spacing, w = (z + half_width) / spacing;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, cells - 1);
  const int j = std::clamp(static_cast<int>(std::floor(w)), 0, cells - 1);
  const double s = u - i, t = w - j;  // local coordinates in the cell, [0, 1]
  const double a = values[j * side + i], b = values[j * side + i + 1],
               c = values[(j + 1) * side + i], d = values[(j + 1) * side + i + 1];
  // Triangle (a, c, d) holds t ≥ s, triangle (a, d, b) holds s ≥ t.
  return t >= s ? a + s * (d - c) + t * (c - a) : a + s * (b - a) + t * (d - b);
}

}  // namespace ergo::testing
