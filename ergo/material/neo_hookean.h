// Invertible isotropic neo-Hookean material with compression resistance (DESIGN.md §3
// "Material", the paper's §3.3): energy density psi(F) in J/m^3, first Piola-Kirchhoff
// stress P = dpsi/dF in Pa and its derivative dP/dF (9x9, Pa), exact or projected to
// positive semi-definite. Written in signed principal stretches with ln clamped to a C^2
// extension below the inversion threshold, so every F (inverted, singular) gives finite
// values. Derivation and equation numbers: ergo/material/README.md.
#pragma once

#include <Eigen/Core>

#include "ergo/material/principal_hessian.h"
#include "ergo/material/rotation_variant_svd.h"

namespace ergo {

// Which second derivative to return: the exact one (adjoint solves, DESIGN §3) or the
// one with negative curvature removed per element (Newton steps).
enum class HessianKind { kExact, kProjectedPsd };

struct NeoHookeanParameters {
  double youngs_modulus = 1e4;  // E in Pa (soft tissue: 5–15 kPa); > 0
  double poisson_ratio = 0.45;  // nu, in (-1, 0.5)
  // c in k = c E / (1 - 2 nu), the stiffness of psi_c(J) = -k (J - 1)^3 / 2592 for J < 1;
  // dimensionless, >= 0; 0 switches compression resistance off (Vega FEM's flag is 0/1).
  double compression_resistance = 1.0;
  // epsilon: principal stretches below it use the quadratic extension of ln; in (0, 1).
  double inversion_threshold = 0.1;
  // alpha in the stretch term 2 mu / alpha^2 sum_i (sigma_i^alpha - 1) and the log term
  // -(2 mu / alpha) ln J (README §1a): 2 is the neo-Hookean reference form; larger values
  // stiffen the material as it stretches (a compressible one-term Ogden law; the heel pad
  // fits alpha ~ 6.8, Erdemir et al. 2006) with the same small-strain E and nu; in [2, 30].
  double stiffening_exponent = 2.0;
};

struct LameParameters {
  double mu = 0;      // shear modulus, Pa
  double lambda = 0;  // first Lame parameter, Pa
};

// mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)); CHECKs E > 0, -1 < nu < 0.5.
LameParameters LameFromYoungPoisson(double youngs_modulus, double poisson_ratio);

// The material: immutable, cheap to copy, one per tet if E and nu vary per tet.
class NeoHookean {
 public:
  // CHECKs the parameter ranges documented in NeoHookeanParameters.
  explicit NeoHookean(const NeoHookeanParameters& parameters);

  const NeoHookeanParameters& parameters() const { return parameters_; }
  double mu() const { return mu_; }          // Pa
  double lambda() const { return lambda_; }  // Pa
  // k = c E / (1 - 2 nu), Pa.
  double compression_stiffness() const { return compression_stiffness_; }

  // psi(F), J/m^3. Equals the reference form (README eq. 1) when all sigma_i >= epsilon.
  double EnergyDensity(const Eigen::Matrix3d& f) const;
  // P = dpsi/dF, Pa.
  Eigen::Matrix3d FirstPiola(const Eigen::Matrix3d& f) const;
  // dP/dF as a 9x9 matrix, vec(F)[a + 3 b] = F(a, b) (principal_hessian.h), Pa. The exact one is
  // only meaningful away from sigma_i + sigma_j = 0 (README §5), where psi is not twice
  // differentiable in F; there it stays finite.
  Matrix9d StressDerivative(const Eigen::Matrix3d& f, HessianKind kind) const;
  // psi, P and dP/dF in one pass (one SVD); null outputs are skipped.
  void Evaluate(const Eigen::Matrix3d& f, HessianKind kind, double* energy_density,
                Eigen::Matrix3d* first_piola, Matrix9d* stress_derivative) const;

  // The principal-frame pieces of one evaluation, for assembling element Hessians
  // without forming dP/dF: the signed SVD of F and the (exact or projected) principal
  // Hessian. Null outputs are skipped.
  void EvaluatePrincipalFrame(const Eigen::Matrix3d& f, HessianKind kind, double* energy_density,
                              Eigen::Matrix3d* first_piola, SignedSvd3* svd,
                              PrincipalHessian* principal_hessian) const;

  // psi_hat(sigma), J/m^3, for signed principal stretches (README eq. 3).
  double PrincipalEnergy(const Eigen::Vector3d& sigma) const;
  // d psi_hat / d sigma_i, Pa (README eq. 5).
  Eigen::Vector3d PrincipalStress(const Eigen::Vector3d& sigma) const;
  // The blocks of dP/dF in the principal frame (README §4), exact or projected (each
  // eigenvalue clamped at zero).
  PrincipalHessian PrincipalStressDerivative(const Eigen::Vector3d& sigma, HessianKind kind) const;

 private:
  NeoHookeanParameters parameters_;
  double mu_;
  double lambda_;
  double compression_stiffness_;
};

}  // namespace ergo
