// Sliding-anchor penalty energy E = k‖p − π‖² of one skin vertex p against one support
// feature (paper Eq. 10, Appendix A, Eq. 24–32 with DESIGN.md §3's corrections to Eq. 27
// and 29): inside a vertex / edge / face Voronoi region E is exactly k × squared distance
// to a point / line / plane, so value, gradient and Hessian below are exact there — with
// respect to p AND the feature's support vertices. Units: k in N/m, positions in m, E in J.
#pragma once

#include <array>

#include <Eigen/Core>

#include "ergo/contact/feature.h"
#include "ergo/mesh/eigen_types.h"

namespace ergo {

// ---- Vertex region (Eq. 24–26): E = k‖p − v‖². Variables ordered (p, v). ----

// @return k‖p − v‖².
double PointVertexEnergy(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double k);
// @return ∂E/∂(p, v) = 2k (r, −r), r = p − v.
Vector6d PointVertexEnergyGradient(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double k);
// @return ∂²E/∂(p, v)² = 2k [I −I; −I I].
Matrix6d PointVertexEnergyHessian(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double k);

// ---- Edge region (Eq. 27–29 as corrected in DESIGN §3): E = k‖d × e‖²/‖e‖², d = p − e0,
// e = e1 − e0; i.e. k × squared distance from p to the line through e0, e1. Variables
// ordered (p, e0, e1). Requires e0 ≠ e1 (CHECKed). ----

// @return k × squared distance from p to the line (e0, e1).
double PointEdgeEnergy(const Eigen::Vector3d& p, const Eigen::Vector3d& e0,
                       const Eigen::Vector3d& e1, double k);
// @return ∂E/∂(p, e0, e1) = 2k (r, −(1 − t) r, −t r), r = p − anchor, t the edge parameter.
Vector9d PointEdgeEnergyGradient(const Eigen::Vector3d& p, const Eigen::Vector3d& e0,
                                 const Eigen::Vector3d& e1, double k);
// @return ∂²E/∂(p, e0, e1)², exact (quotient rule on the polynomials ‖d × e‖², ‖e‖²).
// @note Only the (p, p) block, 2k (I − ê êᵀ) (corrected Eq. 29), is positive semi-definite.
Matrix9d PointEdgeEnergyHessian(const Eigen::Vector3d& p, const Eigen::Vector3d& e0,
                                const Eigen::Vector3d& e1, double k);

// ---- Face region (Eq. 30–32): E = k g²/h, g = (e1 × e2)·d (6 × signed tet volume),
// h = ‖e1 × e2‖², e1 = t1 − t0, e2 = t2 − t0, d = p − t0; i.e. k × squared distance from
// p to the plane of the triangle. Variables ordered (p, t0, t1, t2). Requires a triangle
// of non-zero area (CHECKed). ----

// @return k × squared distance from p to the plane of (t0, t1, t2).
double PointFaceEnergy(const Eigen::Vector3d& p, const Eigen::Vector3d& t0,
                       const Eigen::Vector3d& t1, const Eigen::Vector3d& t2, double k);
// @return ∂E/∂(p, t0, t1, t2) = 2k s n (1, −b0, −b1, −b2), s the signed distance, n the unit
// normal, b the barycentric coordinates of the anchor.
Vector12d PointFaceEnergyGradient(const Eigen::Vector3d& p, const Eigen::Vector3d& t0,
                                  const Eigen::Vector3d& t1, const Eigen::Vector3d& t2, double k);
// @return ∂²E/∂(p, t0, t1, t2)², exact (quotient rule on the polynomials g², h).
// @note Only the (p, p) block, 2k n nᵀ (Eq. 32), is positive semi-definite.
Matrix12d PointFaceEnergyHessian(const Eigen::Vector3d& p, const Eigen::Vector3d& t0,
                                 const Eigen::Vector3d& t1, const Eigen::Vector3d& t2, double k);

// ---- Any region, chosen by the feature type. ----

// Positions of a feature's support vertices in Feature::vertices order; entries past
// FeatureVertexCount(type) are ignored.
using FeaturePositions = std::array<Eigen::Vector3d, 3>;

// The anchor π(p) on the feature's point / line / plane (Eq. 24, corrected 27, 30).
Eigen::Vector3d SlidingAnchor(FeatureType type, const Eigen::Vector3d& p,
                              const FeaturePositions& x);

// Energy with gradient and Hessian over (p, x0, …, x_{n−1}), n = FeatureVertexCount(type):
// only the leading size = 3(n + 1) entries / rows / columns are set, the rest are zero.
struct SlidingAnchorEnergy {
  double energy = 0.0;
  int size = 0;
  Vector12d gradient = Vector12d::Zero();
  Matrix12d hessian = Matrix12d::Zero();
};

// Evaluates E = k‖p − π‖² with `type`'s formula; skips the Hessian if !with_hessian.
SlidingAnchorEnergy EvaluateSlidingAnchor(FeatureType type, const Eigen::Vector3d& p,
                                          const FeaturePositions& x, double k,
                                          bool with_hessian = true);

}  // namespace ergo
