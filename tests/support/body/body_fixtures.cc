#include "tests/support/body/body_fixtures.h"

#include <vector>

#include "ergo/mesh/primitives.h"

namespace ergo::testing {

LayeredBody MakeHollowCubeBody(double size, int cells, double youngs_modulus, double poisson_ratio,
                               const LayeredBodyOptions& options, const Eigen::Vector3d& centre,
                               const Eigen::Matrix3d& orientation) {
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(size / 2);
  const TetMesh grid = MakeTetGrid(centre - half, centre + half, Eigen::Vector3i::Constant(cells));
  const double lo = -size / 6, hi = size / 6;  // the middle third is the core
  auto inside_core = [&](const Eigen::Vector3d& p, double tolerance) {
    const Eigen::Vector3d q = p - centre;
    return (q.array() > lo - tolerance).all() && (q.array() < hi + tolerance).all();
  };
  TetMesh layer;
  layer.vertices = grid.vertices;
  std::vector<int> kept;
  for (Eigen::Index t = 0; t < grid.tets.rows(); ++t) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += grid.vertices.row(grid.tets(t, k)).transpose() / 4;
    if (!inside_core(centroid, 0)) kept.push_back(static_cast<int>(t));
  }
  layer.tets.resize(static_cast<Eigen::Index>(kept.size()), 4);
  for (size_t i = 0; i < kept.size(); ++i) layer.tets.row(i) = grid.tets.row(kept[i]);
  std::vector<bool> attached(static_cast<size_t>(layer.vertices.rows()));
  const double eps = 1e-9 * size;
  for (Eigen::Index v = 0; v < layer.vertices.rows(); ++v)
    attached[v] = inside_core(layer.vertices.row(v).transpose(), eps);
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(layer.tets.rows(), youngs_modulus);
  material.poisson_ratio = Eigen::VectorXd::Constant(layer.tets.rows(), poisson_ratio);
  // Vertices strictly inside the core are unused by any tet; they stay as attached,
  // massless vertices (harmless: they move with the core).
  for (Eigen::Index v = 0; v < layer.vertices.rows(); ++v) {
    layer.vertices.row(v) =
        (centre + orientation * (layer.vertices.row(v).transpose() - centre)).transpose();
  }
  return LayeredBody::Create(layer, attached, material, options, "hollow cube");
}

}  // namespace ergo::testing
