// SupportParameterization: the design vector x of paper §4 and how it moves the support.
// Three kinds behind one interface: the positions of an active subset of support vertices
// (3 numbers each; e.g. only the chair's top face moves), their displacement along the initial
// vertex normals (one number each), or a filtered normal displacement x = x₀ + N·F·θ (one θ
// each) with the Helmholtz filter F of physical radius r. Units: metres.
//
// The filter (kFiltered; Lazarov & Sigmund 2011, DESIGN.md §8). F = (M + R²K)⁻¹ M with K the
// cotangent stiffness (ergo/mesh/cotangent_stiffness.h) and M the lumped (barycentric) mass,
// both over the designed triangles (all three corners active), and R = r/(2√3): F smooths θ (m)
// into a surface whose features are about r wide however finely the support is meshed, which
// makes designs mesh-independent. A ripple cos(kx)·cos(kz) of wavelength r keeps
// 1/(1 + 2R²k²) = 0.13 of its height; the checkerboard of a square grid of spacing h keeps
// 1/(1 + 2r²/3h²), 0.27 at r = 2h.
// Assembling only over designed triangles gives the natural (Neumann) boundary at the rim of
// the designed region. F·1 = 1 (K·1 = 0): constants pass unchanged. An active vertex in no
// designed (non-degenerate) triangle is filtered by the identity: its θ moves it alone, as in
// kNormalDisplacement. A = M + R²K is factorised once, in the constructor.
// Why the transpose matters: dφ/dθ = Fᵀ Nᵀ ∂φ/∂x with Fᵀ = M A⁻¹ (A is symmetric), which is
// not F wherever vertex areas differ (the rim has half areas). PolyFEM's LinearFilter once
// applied the forward matrix where the transpose was needed. The pull-back is checked by finite
// differences in tests/design/support_parameterization_test.cc, where F fails the same check.
//
// The optimiser's metric (kFiltered with `l2_metric`). θ holds one value per vertex, so the
// Euclidean inner product an optimiser uses weighs each variable by its vertex area:
// ∂φ/∂θᵢ ∝ mᵢ, and a steepest-descent step is 4× shorter on a support of half the spacing
// (measured on the quick shoe: 0.126 mm against 0.027 mm on 10 and 5 mm soles). With the L²
// metric the design variables are θ̃ = W θ, Wᵢ = √(mᵢ/a) with a fixed physical area
// a = (r/2.5)² (the skin edge the default radius comes from): Σ θ̃ᵢ² = ∫ θ² dA / a and
// ‖∂φ/∂θ̃‖ no longer depend on the mesh. A vertex-move cap m becomes the box |θ̃ᵢ| ≤ m·min W
// (BoxHalfWidthForMove), the same fraction of the cap on every mesh.
//
// The spline space (kSpline; ergo/design/spline_lattice.h): x = x₀ + N·B·c, c the control
// values of a cubic B-spline lattice in space of knot spacing r (the `filter_radius`), B its
// weights at the designed vertices. The design variables are the same on every mesh of the
// support: a 10 and a 5 mm sole sample one function of the same controls, and the optimiser's
// Euclidean inner product on c is the same on both. B ≥ 0 with rows summing to 1, so
// |d| ≤ max|c| (the box for a move cap is the cap itself). Pull-back: Bᵀ, exact.
//
// Threads: copies share nothing (each owns its CHOLMOD factor and workspace), so copies may
// be used from different threads; one object must not be used from two threads at once
// (kFiltered's const methods use the factor's solve workspace).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

enum class DesignParameterization { kPositions, kNormalDisplacement, kFiltered, kSpline };

class SupportParameterization {
 public:
  // `active` flags support vertices that may move (empty = all). Normals are the
  // area-weighted vertex normals of `initial`. `filter_radius` r (m, > 0) is required by
  // kFiltered and kSpline (its knot spacing) and ignored by the other kinds; `l2_metric`
  // applies to kFiltered only (see above).
  SupportParameterization(const TriMesh& initial, std::vector<bool> active,
                          DesignParameterization kind, double filter_radius = 0,
                          bool l2_metric = false);

  DesignParameterization kind() const { return kind_; }
  int size() const;  // number of design variables
  const Eigen::VectorXi& active_vertices() const { return active_; }
  // r, m, for kFiltered and kSpline; 0 for the other kinds (they have no filter).
  double filter_radius() const { return filter_radius_; }
  bool l2_metric() const { return l2_metric_; }
  // The half-width of the box on each design variable that keeps every vertex within `move`
  // (m) of where the box's centre puts it.
  double BoxHalfWidthForMove(double move) const;
  // x₀: the initial support's design vector (zeros for the normal kinds).
  Eigen::VectorXd InitialDesign() const;
  // Support vertex positions for design x.
  Vertices Positions(const Eigen::VectorXd& x) const;
  // dφ/dx from dφ/d(vertex positions) (#V x 3): chain rule through Positions(), i.e. the
  // exact transpose of its Jacobian.
  Eigen::VectorXd PullBack(const Vertices& position_gradient) const;
  // Per active vertex, the largest displacement a design step dx causes, m: for the
  // paper-NCG step sizes (largest vertex move) and move limits.
  Eigen::VectorXd VertexMoves(const Eigen::VectorXd& dx) const;
  // The design whose support is closest to `positions` (#V x 3; only active rows are read):
  // their active rows for kPositions; the displacement from x₀ projected on the normals for
  // kNormalDisplacement; for kFiltered that displacement d mapped back through the filter,
  // θ = F⁻¹ d = M⁻¹ A d (exact: F is invertible). DesignFor(Positions(x)) = x. For kSpline
  // the least-squares fit of the displacement, min ‖Bc − d‖² + ε‖c‖² with ε tiny (the
  // minimum-norm controls: a flat region is reached by several layers of the lattice), so
  // Positions(DesignFor(p)) = p only for p in the spline space.
  Eigen::VectorXd DesignFor(const Vertices& positions) const;

 private:
  void BuildFilter(const TriMesh& initial);
  void BuildSpline();
  // d = F θ and Fᵀ g (both #active); with the L² metric θ = W⁻¹ θ̃ inside.
  Eigen::VectorXd Filter(const Eigen::VectorXd& theta) const;
  Eigen::VectorXd FilterTransposed(const Eigen::VectorXd& g) const;
  // Per active vertex its displacement along the normal for design x (not kPositions).
  Eigen::VectorXd AlongNormal(const Eigen::VectorXd& x) const;
  // Per active vertex the displacement along its normal of the support at `positions`.
  Eigen::VectorXd NormalDisplacements(const Vertices& positions) const;

  Vertices initial_;
  Vertices normals_;
  Eigen::VectorXi active_;
  DesignParameterization kind_;
  double filter_radius_ = 0;
  bool l2_metric_ = false;
  // kFiltered, over the active vertices: the lumped mass M (m²; the mean designed vertex area
  // stands in for vertices in no designed triangle), A = M + R²K, and A's factor.
  Eigen::VectorXd filter_mass_;
  Eigen::VectorXd metric_weight_;  // W (ones without the L² metric)
  SparseMatrix filter_matrix_;
  SparseCholesky filter_cholesky_;
  // kSpline: B, #active x controls.
  SparseMatrix spline_basis_;
};

}  // namespace ergo
