// SplineLattice: a trivariate uniform cubic B-spline on a lattice of knot spacing s, sampled at
// a set of points — the matrix B with d = B·c, d one value per point, c one value per control
// point of the lattice (only the controls that reach some point are kept).
//
// Why a lattice in space rather than values on the mesh: the design variables are then the
// same on every mesh of the same support. A support meshed at 10 or at 5 mm samples the same
// function d(p) = Σ_j N((p − o)/s − j)·c_j (N the tensor product of cubic B-splines), so two
// optimisations on the two meshes search the same space with the same inner product, and no
// feature narrower than the knot spacing can form whatever the mesh (the "spline control net"
// of issue 20's design spaces; a free-form deformation lattice, Sederberg & Parry 1986,
// restricted to one component). Working in 3D instead of the support's base plane keeps
// curved designed regions (the mouse's shell, the chair's front arc) single-valued.
//
// Properties the design space relies on (tests/design/spline_design_space_test.cc): the weights of
// a row are ≥ 0 and sum to 1 (partition of unity), so a constant field passes unchanged and
// |d| ≤ max|c|; a row has at most 64 non-zeros; a field linear in space is reproduced exactly
// by its control values at the knots' Greville points (the knots themselves for cubics).
//
// The origin must not depend on the mesh either: SupportParameterization puts it half a
// spacing below the lowest corner of the whole support (the same geometry on every mesh; the
// designed vertices' own corner moves with the mesh, by one spacing at a fixed rim), which
// also keeps the scenes' flat tops off the knot planes. Where a point does lie on a knot
// plane, the controls of that plane's outer neighbours get zero weight and are dropped.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace ergo {

class SplineLattice {
 public:
  // `points` #P x 3, spacing s > 0 (m), knots at origin + s·(i, j, k).
  SplineLattice(const Eigen::MatrixXd& points, double spacing, const Eigen::Vector3d& origin);

  int control_count() const { return static_cast<int>(controls_.rows()); }
  // Lattice coordinates (i, j, k) of each kept control; its position is origin + s·(i, j, k).
  const Eigen::MatrixXi& controls() const { return controls_; }
  Eigen::Vector3d ControlPosition(int control) const;
  // B: #P x control_count.
  const Eigen::SparseMatrix<double>& basis() const { return basis_; }

  // The uniform cubic B-spline N(t) (support |t| < 2, N(0) = 2/3).
  static double CubicBSpline(double t);

 private:
  double spacing_;
  Eigen::Vector3d origin_;
  Eigen::MatrixXi controls_;
  Eigen::SparseMatrix<double> basis_;
};

}  // namespace ergo
