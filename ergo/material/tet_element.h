// One linear tetrahedron of neo-Hookean tissue (ergo/material/neo_hookean.h): elastic
// energy E = V psi(F) in J, its gradient (N) and 12x12 Hessian (N/m) with respect to the
// four vertex positions, F = Ds Dm^-1 (README §6). Positions are vertex-major
// (x0, y0, z0, x1, ...), the order of a TetMesh's row-major vertex block.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "ergo/material/neo_hookean.h"
#include "ergo/mesh/eigen_types.h"

namespace ergo {

// Column v is vertex v; column-major storage makes it the same memory as a Vector12d.
using TetPositions = Eigen::Matrix<double, 3, 4>;

// What a tet needs from its rest shape.
struct TetRestData {
  Eigen::Matrix3d dm_inverse;  // Dm^-1, Dm = [X1 - X0, X2 - X0, X3 - X0], 1/m
  double volume = 0;           // rest volume V, m^3
};

// (x1 - x0) . ((x2 - x0) x (x3 - x0)) / 6, m^3; positive for a positively oriented tet.
double SignedTetVolume(const TetPositions& x);

// Rest data from the rest positions, or std::nullopt if the signed rest volume is
// <= min_volume (degenerate or inverted rest tet): the caller reports that element.
std::optional<TetRestData> ComputeTetRestData(const TetPositions& rest, double min_volume = 0.0);

// F = Ds Dm^-1, Ds = [x1 - x0, x2 - x0, x3 - x0].
Eigen::Matrix3d DeformationGradient(const TetRestData& rest, const TetPositions& x);

// The 4x3 matrix G with F = sum_v x_v G_v^T (rows 1..3 are Dm^-1, row 0 minus their sum),
// so dF_ab/dx_vc = delta_ac G_vb. 1/m.
Eigen::Matrix<double, 4, 3> ShapeGradients(const TetRestData& rest);

// dE/dx from the stress: vertex v gets V P G_v (G from ShapeGradients), N.
Vector12d ElementGradientFromStress(const TetRestData& rest, const Eigen::Matrix3d& p);

// d2E/dx2 = V D^T (dP/dF) D, D = dvec(F)/dx, exploiting its Kronecker structure (no
// dense 9x12 product); PSD whenever dP/dF is. N/m. (EvaluateElement does not form dP/dF
// at all: it maps the principal-frame Hessian directly, README §6.)
Matrix12d ElementHessianFromStressDerivative(const TetRestData& rest,
                                             const Matrix9d& stress_derivative);

// Elastic energy V psi(F), J.
double ElementEnergy(const NeoHookean& material, const TetRestData& rest, const TetPositions& x);

// Gradient of ElementEnergy (minus the elastic forces on the 4 vertices), N.
Vector12d ElementGradient(const NeoHookean& material, const TetRestData& rest,
                          const TetPositions& x);

// Hessian of ElementEnergy, exact or per-element PSD-projected, N/m.
Matrix12d ElementHessian(const NeoHookean& material, const TetRestData& rest, const TetPositions& x,
                         HessianKind kind);

// Energy, gradient and Hessian from one SVD (the assembly's call); null outputs are
// skipped, so energy + gradient alone costs no Hessian work.
void EvaluateElement(const NeoHookean& material, const TetRestData& rest, const TetPositions& x,
                     HessianKind kind, double* energy, Vector12d* gradient, Matrix12d* hessian);

}  // namespace ergo
