// Linearly precise biharmonic interpolation of values given at scattered points of a surface:
// the paper's §6 puts its 78 measured sensor pressures onto the shoe sole's vertices "using
// linearly precise biharmonic weights" (Wang, Jacobson, Barbič & Kavan 2015), each sensor a
// handle. The field u on the vertices minimises the squared-Laplacian energy
//   E(u) = uᵀ Q u,   Q = L̃ᵀ M⁻¹ L̃
// (L̃ the linearly precise Laplacian, linearly_precise_laplacian.h; M the lumped barycentric
// vertex areas) subject to B u = v: row j of B holds handle j's barycentric coordinates in its
// triangle, so handles need not sit on vertices. Solved with one sparse Cholesky
// factorisation (CHOLMOD) of A = Q + ρ BᵀB — positive definite once the handles pin E's null
// space (for a connected planar patch: three handles not on one line), and the added term is
// constant on the constraint set, so the minimiser is the same — then one back-substitution
// per handle: Z = A⁻¹Bᵀ, S = B Z (#handles²), and u = W v with the weights W = Z S⁻¹. The
// weights interpolate (B W = I) and reproduce constant and linear functions exactly on a
// planar surface (E vanishes on them). Values keep their unit; weights are dimensionless.
//
//   const BiharmonicWeights w = ComputeBiharmonicWeights(top, sensor_points);
//   if (!w.ok) throw InputError(path, "", w.message, "...");
//   const Eigen::VectorXd pressure_on_vertices = w.Interpolate(sensor_pressures);
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// A point of a surface: its triangle and barycentric coordinates there (summing to 1).
struct SurfacePoint {
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

struct BiharmonicOptions {
  // true: L̃ with the boundary flux (linearly precise). false: the classic K M⁻¹ K of
  // Jacobson et al. 2011 ("Bounded Biharmonic Weights"), whose implicit zero-Neumann boundary
  // is not linearly precise; kept to show the difference.
  bool linearly_precise = true;
};

struct BiharmonicWeights {
  bool ok = false;
  std::string message;      // why not ok: which condition failed
  Eigen::MatrixXd weights;  // #V x #handles

  // u = W v: one value per handle in, one per vertex out.
  Eigen::VectorXd Interpolate(const Eigen::VectorXd& handle_values) const;
};

// The weights of `handles` on `surface` (metres). Not ok, with a message, when the handles do
// not determine a unique field (fewer than three, all on one line, or a part of the surface
// without any) or two of them coincide.
BiharmonicWeights ComputeBiharmonicWeights(const TriMesh& surface,
                                           const std::vector<SurfacePoint>& handles,
                                           const BiharmonicOptions& options = {});

}  // namespace ergo
