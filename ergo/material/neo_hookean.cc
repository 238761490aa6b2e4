#include "ergo/material/neo_hookean.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>

namespace ergo {
namespace {

// psi_c(J) = -k (J - 1)^3 / 2592 for J < 1 (README eq. 2); 2592 = 3 * 864 = 6 * 432.
constexpr double kCompressionDenominator = 2592.0;

// Below this |sigma_i + sigma_j| (times epsilon) the sum quotient's denominator is
// floored (README §5): the energy has a kink in F there and the exact Hessian diverges.
constexpr double kPairSumFloorOverThreshold = 1e-6;

constexpr int kPairFirst[3] = {0, 0, 1};
constexpr int kPairSecond[3] = {1, 2, 2};

// Jacobi refinement of the 3x3 stretch block's eigenvectors (ProjectToPsd).
constexpr double kJacobiTolerance = 1e-16;
constexpr int kMaxJacobiSweeps = 4;

// The constants of psi_hat (README eqs. 1, 1a, 2).
struct Coefficients {
  double stretch = 0;  // 2 mu / alpha^2
  double log = 0;      // 2 mu / alpha
  double lambda = 0;
  double compression = 0;  // k
  double alpha = 2;
  double epsilon = 0.1;
};

// Everything about psi_hat(sigma) that P and dP/dF need (README eqs. 3-7).
struct PrincipalState {
  Eigen::Vector3d sigma;
  Eigen::Vector3d stretch_slope;      // d/dsigma_i of the stretch term, Pa
  Eigen::Vector3d stretch_curvature;  // d2/dsigma_i^2 of the stretch term, Pa
  Eigen::Vector3d log_slope;          // l'(sigma_i)
  Eigen::Vector3d log_curvature;      // l''(sigma_i)
  bool all_above_threshold = true;
  double log_volume = 0;      // L = sum_i l(sigma_i)
  double volume = 1;          // J~ = exp(L)
  double energy = 0;          // psi_hat
  double coupling = 0;        // G = lambda L - 2 mu / alpha + J~ psi_c'(J~)
  double coupling_slope = 0;  // dG/dL = lambda + J~ psi_c' + J~^2 psi_c''
};

// Symmetric 3x3 with negative eigenvalues clamped to zero. A positive-definite input
// (Sylvester's criterion) is returned unchanged, so the projection is exact near rest.
Eigen::Matrix3d ProjectToPsd(const Eigen::Matrix3d& m) {
  const double minor1 = m(0, 0);
  const double minor2 = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  if (minor1 > 0 && minor2 > 0 && m.determinant() > 0) return m;
  // Closed-form eigenvectors are only accurate to ~sqrt(eps) near a double eigenvalue
  // (here common: equal stretches make the block a I + b 11^T) and lose orthogonality;
  // re-orthonormalise them, then finish with cyclic Jacobi on Q^T m Q, which converges
  // quadratically from there (one sweep, plus one to confirm).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(m);
  Eigen::Matrix3d q;
  q.col(0) = eigen.eigenvectors().col(0).normalized();
  q.col(1) = eigen.eigenvectors().col(1) - q.col(0).dot(eigen.eigenvectors().col(1)) * q.col(0);
  q.col(1).normalize();
  q.col(2) = q.col(0).cross(q.col(1));
  Eigen::Matrix3d a = q.transpose() * m * q;
  for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
    bool rotated = false;
    for (int pair = 0; pair < 3; ++pair) {
      const int i = kPairFirst[pair];
      const int j = kPairSecond[pair];
      const double off = a(i, j);
      if (std::abs(off) <= kJacobiTolerance * (std::abs(a(i, i)) + std::abs(a(j, j)))) continue;
      rotated = true;
      // Rotation J with J^T a J zero at (i, j); t = tan(theta), |theta| <= pi/4.
      const double theta = (a(j, j) - a(i, i)) / (2.0 * off);
      const double t = std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1));
      const double c = 1.0 / std::sqrt(t * t + 1);
      const double s = t * c;
      Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
      rotation(i, i) = c;
      rotation(j, j) = c;
      rotation(i, j) = s;
      rotation(j, i) = -s;
      a = (rotation.transpose() * a * rotation).eval();
      a(i, j) = a(j, i) = 0.0;
      q = (q * rotation).eval();
    }
    if (!rotated) break;
  }
  const Eigen::Vector3d clamped = a.diagonal().cwiseMax(0.0);
  return q * clamped.asDiagonal() * q.transpose();
}

}  // namespace

LameParameters LameFromYoungPoisson(double youngs_modulus, double poisson_ratio) {
  CHECK_GT(youngs_modulus, 0.0) << "Young's modulus must be positive (Pa)";
  CHECK(poisson_ratio > -1.0 && poisson_ratio < 0.5)
      << "Poisson ratio must be in (-1, 0.5), got " << poisson_ratio;
  LameParameters lame;
  lame.mu = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  lame.lambda =
      youngs_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  return lame;
}

NeoHookean::NeoHookean(const NeoHookeanParameters& parameters) : parameters_(parameters) {
  const LameParameters lame =
      LameFromYoungPoisson(parameters.youngs_modulus, parameters.poisson_ratio);
  CHECK_GE(parameters.compression_resistance, 0.0);
  CHECK(parameters.inversion_threshold > 0.0 && parameters.inversion_threshold < 1.0)
      << "inversion threshold must be in (0, 1), got " << parameters.inversion_threshold;
  CHECK(parameters.stiffening_exponent >= 2.0 && parameters.stiffening_exponent <= 30.0)
      << "stiffening exponent must be in [2, 30], got " << parameters.stiffening_exponent;
  mu_ = lame.mu;
  lambda_ = lame.lambda;
  compression_stiffness_ = parameters.compression_resistance * parameters.youngs_modulus /
                           (1.0 - 2.0 * parameters.poisson_ratio);
}

namespace {

Coefficients CoefficientsOf(const NeoHookean& material) {
  Coefficients c;
  c.alpha = material.parameters().stiffening_exponent;
  c.stretch = 2.0 * material.mu() / (c.alpha * c.alpha);
  c.log = 2.0 * material.mu() / c.alpha;
  c.lambda = material.lambda();
  c.compression = material.compression_stiffness();
  c.epsilon = material.parameters().inversion_threshold;
  return c;
}

// w(sigma) = sigma^alpha and its first two derivatives, continued below epsilon by its
// quadratic Taylor polynomial (README eq. 4a) so that inverted stretches stay finite and
// C^2; alpha = 2 is sigma^2 itself (its Taylor polynomial), evaluated directly.
void StretchPower(double sigma, double alpha, double epsilon, double* w, double* slope,
                  double* curvature) {
  if (alpha == 2.0) {
    *w = sigma * sigma;
    *slope = 2.0 * sigma;
    *curvature = 2.0;
    return;
  }
  const double base = sigma >= epsilon ? sigma : epsilon;
  const double power = std::pow(base, alpha - 2.0);  // base^(alpha-2)
  const double w0 = power * base * base, w1 = alpha * power * base,
               w2 = alpha * (alpha - 1.0) * power;
  if (sigma >= epsilon) {
    *w = w0;
    *slope = w1;
    *curvature = w2;
    return;
  }
  const double d = sigma - epsilon;
  *w = w0 + w1 * d + 0.5 * w2 * d * d;
  *slope = w1 + w2 * d;
  *curvature = w2;
}

// The principal-space state of psi_hat at sigma (README eqs. 3-6).
PrincipalState EvaluatePrincipal(const Eigen::Vector3d& sigma, const Coefficients& c) {
  const double lambda = c.lambda, k = c.compression, epsilon = c.epsilon;
  PrincipalState s;
  s.sigma = sigma;
  double stretch_energy = 0;
  for (int i = 0; i < 3; ++i) {
    double w = 0;
    StretchPower(sigma(i), c.alpha, epsilon, &w, &s.stretch_slope(i), &s.stretch_curvature(i));
    stretch_energy += w - 1.0;
  }
  s.stretch_slope *= c.stretch;
  s.stretch_curvature *= c.stretch;
  for (int i = 0; i < 3; ++i) s.all_above_threshold &= sigma(i) >= epsilon;
  if (s.all_above_threshold) {
    // Common case: l = ln, one log instead of three logs and an exp.
    s.volume = sigma(0) * sigma(1) * sigma(2);
    s.log_volume = std::log(s.volume);
    s.log_slope = sigma.cwiseInverse();
    s.log_curvature = -s.log_slope.cwiseAbs2();
  } else {
    const double inv_eps = 1.0 / epsilon;
    const double log_eps = std::log(epsilon);
    for (int i = 0; i < 3; ++i) {
      if (sigma(i) >= epsilon) {
        s.log_volume += std::log(sigma(i));
        s.log_slope(i) = 1.0 / sigma(i);
        s.log_curvature(i) = -s.log_slope(i) * s.log_slope(i);
      } else {
        // C^2 quadratic Taylor extension of ln at epsilon (README eq. 4).
        const double d = (sigma(i) - epsilon) * inv_eps;
        s.log_volume += log_eps + d - 0.5 * d * d;
        s.log_slope(i) = (1.0 - d) * inv_eps;
        s.log_curvature(i) = -inv_eps * inv_eps;
      }
    }
    s.volume = std::exp(s.log_volume);
  }
  const double l = s.log_volume;
  const double j = s.volume;
  double psi_c = 0, dpsi_c = 0, d2psi_c = 0;
  if (j < 1.0) {
    const double m = j - 1.0;
    psi_c = -k * m * m * m / kCompressionDenominator;
    dpsi_c = -3.0 * k * m * m / kCompressionDenominator;
    d2psi_c = -6.0 * k * m / kCompressionDenominator;
  }
  s.energy = c.stretch * stretch_energy - c.log * l + 0.5 * lambda * l * l + psi_c;
  s.coupling = lambda * l - c.log + j * dpsi_c;
  s.coupling_slope = lambda + j * dpsi_c + j * j * d2psi_c;
  return s;
}

// (l'(a) - l'(b)) / (a - b), exact and cancellation-free for a ~ b (README eq. 8).
double LogSlopeDividedDifference(double a, double b, double epsilon) {
  const bool a_above = a >= epsilon;
  const bool b_above = b >= epsilon;
  if (a_above && b_above) return -1.0 / (a * b);
  if (!a_above && !b_above) return -1.0 / (epsilon * epsilon);
  if (!a_above) std::swap(a, b);  // now a >= epsilon > b
  // l'(a) - l'(b) = [l'(a) - l'(eps)] + [l'(eps) - l'(b)], both parts negative, and
  // a - b = (a - eps) + (eps - b), both parts non-negative: a weighted mean of
  // -1/(a eps) and -1/eps^2, no cancellation anywhere.
  const double above = a - epsilon;
  const double below = epsilon - b;
  return -(above / (a * epsilon) + below / (epsilon * epsilon)) / (above + below);
}

// c_s (w'(sigma_i) - w'(sigma_j)) / (sigma_i - sigma_j) without cancellation for
// sigma_i ~ sigma_j (README eq. 8a), from the state's scaled slopes and curvatures (no
// further powers): above epsilon c_s alpha a^(alpha-2) expm1((alpha-1) t) / expm1(t) with
// t = ln(b / a), where c_s alpha a^(alpha-2) = c_s w'(a) / a.
double StretchSlopeDividedDifference(const PrincipalState& s, int i, int j, const Coefficients& c) {
  if (c.alpha == 2.0) return 2.0 * c.stretch;
  const double epsilon = c.epsilon;
  if (s.sigma(i) < epsilon && s.sigma(j) < epsilon) return s.stretch_curvature(i);  // w'' const
  if (s.sigma(i) < epsilon) std::swap(i, j);  // now sigma_i >= epsilon
  const double a = s.sigma(i), b = s.sigma(j);
  const auto from_a = [&](double y) {
    const double t = std::log1p((y - a) / a);
    if (t == 0.0) return s.stretch_curvature(i);
    return s.stretch_slope(i) / a * std::expm1((c.alpha - 1.0) * t) / std::expm1(t);
  };
  if (b >= epsilon) return from_a(b);
  // Across epsilon: a weighted mean of the two pieces' slopes, as in LogSlopeDividedDifference.
  const double upper = a - epsilon, lower = epsilon - b;
  return (upper * from_a(epsilon) + lower * s.stretch_curvature(j)) / (upper + lower);
}

Eigen::Vector3d StressFromState(const PrincipalState& s) {
  return s.stretch_slope + s.coupling * s.log_slope;
}

PrincipalHessian HessianFromState(const PrincipalState& s, const Coefficients& c,
                                  HessianKind kind) {
  const double epsilon = c.epsilon;
  PrincipalHessian h;
  // d2psi/dsigma_i dsigma_j = (c_s w''_i + G l''_i) delta_ij + G_L l'_i l'_j (README eq. 6;
  // neo-Hookean: c_s w'' = mu).
  h.stretch_block = s.coupling_slope * s.log_slope * s.log_slope.transpose();
  h.stretch_block.diagonal() += s.stretch_curvature + s.coupling * s.log_curvature;
  const double floor = kPairSumFloorOverThreshold * epsilon;
  for (int p = 0; p < 3; ++p) {
    const int i = kPairFirst[p];
    const int j = kPairSecond[p];
    h.difference_quotient(p) =
        StretchSlopeDividedDifference(s, i, j, c) +
        s.coupling * LogSlopeDividedDifference(s.sigma(i), s.sigma(j), epsilon);
    double sum = s.sigma(i) + s.sigma(j);
    // Signed floor; |sum| < floor goes to +floor, the side the SVD ordering
    // sigma2 >= |sigma3| approaches from (README §5).
    if (sum < floor && sum > -floor) sum = floor;
    // Neo-Hookean: the stretch part (mu sigma_i + mu sigma_j) / (sigma_i + sigma_j) = mu exactly.
    const double stretch_part =
        c.alpha == 2.0 ? 2.0 * c.stretch : (s.stretch_slope(i) + s.stretch_slope(j)) / sum;
    h.sum_quotient(p) = stretch_part + s.coupling * (s.log_slope(i) + s.log_slope(j)) / sum;
  }
  if (kind == HessianKind::kProjectedPsd) {
    h.stretch_block = ProjectToPsd(h.stretch_block);
    h.difference_quotient = h.difference_quotient.cwiseMax(0.0);
    h.sum_quotient = h.sum_quotient.cwiseMax(0.0);
  }
  return h;
}

}  // namespace

void NeoHookean::EvaluatePrincipalFrame(const Eigen::Matrix3d& f, HessianKind kind,
                                        double* energy_density, Eigen::Matrix3d* first_piola,
                                        SignedSvd3* svd,
                                        PrincipalHessian* principal_hessian) const {
  const SignedSvd3 decomposition = RotationVariantSvd(f);
  const Coefficients c = CoefficientsOf(*this);
  const PrincipalState s = EvaluatePrincipal(decomposition.sigma, c);
  if (energy_density != nullptr) *energy_density = s.energy;
  if (first_piola != nullptr) {
    // P = U diag(dpsi/dsigma) V^T (README eq. 7).
    first_piola->noalias() =
        decomposition.u * StressFromState(s).asDiagonal() * decomposition.v.transpose();
  }
  if (svd != nullptr) *svd = decomposition;
  if (principal_hessian != nullptr) {
    *principal_hessian = HessianFromState(s, c, kind);
  }
}

void NeoHookean::Evaluate(const Eigen::Matrix3d& f, HessianKind kind, double* energy_density,
                          Eigen::Matrix3d* first_piola, Matrix9d* stress_derivative) const {
  if (stress_derivative == nullptr) {
    EvaluatePrincipalFrame(f, kind, energy_density, first_piola, nullptr, nullptr);
    return;
  }
  SignedSvd3 svd;
  PrincipalHessian h;
  EvaluatePrincipalFrame(f, kind, energy_density, first_piola, &svd, &h);
  *stress_derivative = StressDerivativeFromPrincipal(svd, h);
}

double NeoHookean::EnergyDensity(const Eigen::Matrix3d& f) const {
  double energy = 0;
  Evaluate(f, HessianKind::kExact, &energy, nullptr, nullptr);
  return energy;
}

Eigen::Matrix3d NeoHookean::FirstPiola(const Eigen::Matrix3d& f) const {
  Eigen::Matrix3d p;
  Evaluate(f, HessianKind::kExact, nullptr, &p, nullptr);
  return p;
}

Matrix9d NeoHookean::StressDerivative(const Eigen::Matrix3d& f, HessianKind kind) const {
  Matrix9d h;
  Evaluate(f, kind, nullptr, nullptr, &h);
  return h;
}

double NeoHookean::PrincipalEnergy(const Eigen::Vector3d& sigma) const {
  return EvaluatePrincipal(sigma, CoefficientsOf(*this)).energy;
}

Eigen::Vector3d NeoHookean::PrincipalStress(const Eigen::Vector3d& sigma) const {
  return StressFromState(EvaluatePrincipal(sigma, CoefficientsOf(*this)));
}

PrincipalHessian NeoHookean::PrincipalStressDerivative(const Eigen::Vector3d& sigma,
                                                       HessianKind kind) const {
  const Coefficients c = CoefficientsOf(*this);
  return HessianFromState(EvaluatePrincipal(sigma, c), c, kind);
}

}  // namespace ergo
