// The ergonomic cost of one contact surface (paper §4.1, Eq. 11–12): vertex pressures
// p_i = ‖f_i‖/s_i from the contact forces and barycentric areas, smoothed
// P̄ = (I − λ_p L) P with the umbrella Laplacian L = I − A (DESIGN.md §3; λ_p = 1 is the
// paper's literal formula), and ζ_surface = Σ_i s_i P̄_i^e. The full ζ is the sum over the
// human skin and the support (bi-directional). Also the derivatives of ζ_surface with
// respect to every ‖f_i‖ and s_i, which the adjoint gradient chains. Units: N, m², Pa.
#pragma once

#include <Eigen/Core>

#include "ergo/mesh/laplacian.h"

namespace ergo {

struct PressureCostOptions {
  int exponent = 3;        // e ∈ {2, 3, 4}
  double smoothing = 1.0;  // λ_p ∈ [0, 1]
};

struct SurfacePressure {
  Eigen::VectorXd pressure;  // P, Pa (0 where there is no contact)
  Eigen::VectorXd smoothed;  // P̄, Pa
  double cost = 0;           // Σ s_i P̄_i^e
  // ∂cost/∂‖f_i‖ and ∂cost/∂s_i (with P = ‖f‖/s inside), for the adjoint.
  Eigen::VectorXd d_force_magnitude;
  Eigen::VectorXd d_area;
};

// Evaluates one surface. `force_magnitude` and `area` have one entry per vertex of the
// surface whose Laplacian is `laplacian`; areas must be positive where forces are non-zero.
SurfacePressure EvaluateSurfacePressure(const Eigen::VectorXd& force_magnitude,
                                        const Eigen::VectorXd& area, const SparseMatrix& laplacian,
                                        const PressureCostOptions& options);

}  // namespace ergo
