// The ergonomic cost of one contact surface (paper §4.1, Eq. 11–12): vertex pressures
// p_i = L_i/s_i from the vertices' pressure loads and barycentric areas, smoothed P̄ by a
// PressureSmoothing (the paper's umbrella (I − λ_p L) with λ_p = 1 its literal formula, or a
// Helmholtz filter of physical radius), and ζ_surface = Σ_i s_i P̄_i^e. The full ζ is the sum
// over the human skin and the support (bi-directional). Also the derivatives of ζ_surface
// with respect to every L_i and s_i, which the adjoint gradient chains. Units: N, m², Pa.
#pragma once

#include <Eigen/Core>

#include "ergo/ergonomics/pressure_smoothing.h"

namespace ergo {

struct PressureCostOptions {
  int exponent = 3;        // e ∈ {2, 3, 4}
  double smoothing = 1.0;  // λ_p ∈ [0, 1]
  // Radius r of the Helmholtz pressure smoothing, m; 0 = the paper's umbrella Laplacian.
  double smoothing_radius = 0;
};

struct SurfacePressure {
  Eigen::VectorXd pressure;  // P, Pa (0 where there is no contact)
  Eigen::VectorXd smoothed;  // P̄, Pa
  double cost = 0;           // Σ s_i P̄_i^e
  // ∂cost/∂‖f_i‖ and ∂cost/∂s_i (with P = ‖f‖/s inside), for the adjoint.
  Eigen::VectorXd d_force_magnitude;
  Eigen::VectorXd d_area;
};

// Evaluates one surface. `force_magnitude` (the loads L_i = p_i s_i) and `area` have one
// entry per vertex of the surface `smoothing` was built on; areas must be positive where
// loads are non-zero. options.smoothing_radius is not read here (it chose `smoothing`).
SurfacePressure EvaluateSurfacePressure(const Eigen::VectorXd& force_magnitude,
                                        const Eigen::VectorXd& area,
                                        const PressureSmoothing& smoothing,
                                        const PressureCostOptions& options);

// The smoothing the options ask for on `surface`: Helmholtz of options.smoothing_radius, or
// the umbrella when it is 0.
PressureSmoothing MakePressureSmoothing(const TriMesh& surface, const PressureCostOptions& options);

}  // namespace ergo
