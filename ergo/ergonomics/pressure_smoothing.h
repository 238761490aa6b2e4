// The smoothing of vertex pressures before they are scored (paper Eq. 12, P̄ = (I − λL)P):
// either the paper's umbrella Laplacian L = I − A (A averages the 1-ring), whose reach is one
// ring of vertices and so shrinks as a surface is refined, or a Helmholtz filter of physical
// radius r, S = (M + R²K)⁻¹M with R = r/(2√3) (K the cotangent stiffness, M the lumped mass
// of the surface at rest or at its initial shape), P̄ = (1 − λ)P + λSP, which gives the same
// smoothed field on any mesh of the surface (DESIGN.md §8; as the design filter). Matching
// the umbrella's reach on a mesh of edge h (second moment h² against S's 4R²) gives
// r = √3·h. Both operators are fixed linear maps (they do not move with the design).
// Immutable after construction: one object may be used from several threads.
#pragma once

#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

class PressureSmoothing {
 public:
  // The paper's umbrella smoothing over `triangles` (#V = vertex_count).
  static PressureSmoothing Umbrella(const Triangles& triangles, Eigen::Index vertex_count);
  // The Helmholtz filter of radius `radius` (m, > 0) on `surface`. Vertices in no triangle
  // keep their value.
  static PressureSmoothing Helmholtz(const TriMesh& surface, double radius);

  Eigen::Index size() const { return size_; }
  double radius() const { return radius_; }  // 0 for the umbrella
  // P̄ = (I − λ(I − S))P (umbrella: S = A), λ ∈ [0, 1].
  Eigen::VectorXd Apply(const Eigen::VectorXd& pressure, double lambda) const;
  // The transpose, for gradients of functions of P̄.
  Eigen::VectorXd ApplyTransposed(const Eigen::VectorXd& gradient, double lambda) const;

 private:
  struct Filter;
  Eigen::Index size_ = 0;
  double radius_ = 0;
  SparseMatrix laplacian_;                  // umbrella L (radius 0)
  std::shared_ptr<const Filter> filter_;  // (M + R²K) factorised, and M
};

}  // namespace ergo
