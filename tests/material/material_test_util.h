// Shared helpers of the material tests: random rotations and deformation gradients in
// each stretch regime, and the closed-form reference neo-Hookean (DESIGN.md §3), valid
// for uninverted F with every principal stretch >= the inversion threshold.
#pragma once

#include <cmath>
#include <random>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "ergo/material/neo_hookean.h"
#include "ergo/material/tet_element.h"

namespace ergo::material_testing {

inline Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

// F = R1 diag(sigma) R2^T with random rotations.
inline Eigen::Matrix3d DeformationWithStretches(const Eigen::Vector3d& sigma, std::mt19937& rng) {
  return RandomRotation(rng) * sigma.asDiagonal() * RandomRotation(rng).transpose();
}

inline Eigen::Map<const Eigen::Matrix3d> AsMatrix(const Eigen::VectorXd& x) {
  return Eigen::Map<const Eigen::Matrix3d>(x.data());
}

inline Eigen::VectorXd AsVector(const Eigen::Matrix3d& m) {
  return Eigen::Map<const Eigen::Matrix<double, 9, 1>>(m.data());
}

// The stretch regimes every derivative is checked in (epsilon = inversion threshold).
enum class Regime {
  kRandom,          // sigma in [0.5, 2]
  kRepeated,        // two or three equal stretches (divided differences at their limit)
  kNearThreshold,   // some sigma in (epsilon, 2 epsilon): ln still exact, 1/sigma large
  kBelowThreshold,  // some 0 < sigma < epsilon: the quadratic extension of ln
  kInverted,        // det F < 0: sigma3 < 0, sigma2 + sigma3 kept away from 0
};

inline std::string RegimeName(Regime regime) {
  switch (regime) {
    case Regime::kRandom:
      return "random F";
    case Regime::kRepeated:
      return "repeated stretches";
    case Regime::kNearThreshold:
      return "near-inverted F";
    case Regime::kBelowThreshold:
      return "F below the threshold";
    case Regime::kInverted:
      return "inverted F";
  }
  return "";
}

// Signed stretches of the regime. Every stretch stays >= 0.02 epsilon away from epsilon
// itself, where l''' jumps and central differences of the Hessian lose an order.
inline Eigen::Vector3d StretchesFor(Regime regime, double epsilon, int sample, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  switch (regime) {
    case Regime::kRandom:
      return {in(0.5, 2), in(0.5, 2), in(0.5, 2)};
    case Regime::kRepeated: {
      const double a = in(0.5, 2);
      switch (sample % 4) {
        case 0:
          return {a, a, in(0.5, 2)};
        case 1:
          return {a, a, a};
        case 2:
          return {in(0.5, 2), 0.5 * epsilon, 0.5 * epsilon};  // both below
        default:
          return {in(0.5, 2), in(1.1, 1.9) * epsilon, in(1.1, 1.9) * epsilon};
      }
    }
    case Regime::kNearThreshold:
      if (sample % 2 == 0) return {in(0.5, 2), in(0.5, 2), in(1.05, 1.95) * epsilon};
      return {in(0.5, 2), in(1.05, 1.95) * epsilon, in(1.05, 1.95) * epsilon};
    case Regime::kBelowThreshold:
      switch (sample % 3) {
        case 0:
          return {in(0.5, 2), in(0.5, 2), in(0.05, 0.95) * epsilon};
        case 1:
          return {in(0.5, 2), in(0.05, 0.95) * epsilon, in(0.05, 0.95) * epsilon};
        default:
          return {in(0.5, 2), in(1.05, 1.95) * epsilon, in(0.05, 0.95) * epsilon};
      }
    case Regime::kInverted: {
      // sigma3 < 0 and |sigma3| in [0.02, 0.8] sigma2, so sigma2 + sigma3 >= 0.2 sigma2.
      const double s2 = in(0.3, 1.5);
      return {s2 + in(0.0, 1.0), s2, -in(0.02, 0.8) * s2};
    }
  }
  return Eigen::Vector3d::Ones();
}

// Reference form psi = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 + psi_c(J).
inline double CompressionEnergy(double k, double j) {
  return j < 1 ? -k * std::pow(j - 1, 3) / 2592.0 : 0.0;
}
inline double CompressionSlope(double k, double j) {
  return j < 1 ? -k * (j - 1) * (j - 1) / 864.0 : 0.0;
}
inline double CompressionCurvature(double k, double j) {
  return j < 1 ? -k * (j - 1) / 432.0 : 0.0;
}

inline double ReferenceEnergy(const NeoHookean& m, const Eigen::Matrix3d& f) {
  const double j = f.determinant();
  const double log_j = std::log(j);
  return 0.5 * m.mu() * ((f.transpose() * f).trace() - 3) - m.mu() * log_j +
         0.5 * m.lambda() * log_j * log_j + CompressionEnergy(m.compression_stiffness(), j);
}

// P = mu (F - F^-T) + (lambda ln J + J psi_c'(J)) F^-T.
inline Eigen::Matrix3d ReferencePiola(const NeoHookean& m, const Eigen::Matrix3d& f) {
  const double j = f.determinant();
  const Eigen::Matrix3d f_inv_t = f.inverse().transpose();
  return m.mu() * (f - f_inv_t) +
         (m.lambda() * std::log(j) + j * CompressionSlope(m.compression_stiffness(), j)) * f_inv_t;
}

// dP = mu dF + (mu - lambda ln J - J psi_c') F^-T dF^T F^-T
//      + (lambda + J psi_c' + J^2 psi_c'') (F^-T : dF) F^-T.
inline Matrix9d ReferenceStressDerivative(const NeoHookean& m, const Eigen::Matrix3d& f) {
  const double j = f.determinant();
  const double k = m.compression_stiffness();
  const Eigen::Matrix3d f_inv_t = f.inverse().transpose();
  const double a = m.mu() - m.lambda() * std::log(j) - j * CompressionSlope(k, j);
  const double b = m.lambda() + j * CompressionSlope(k, j) + j * j * CompressionCurvature(k, j);
  Matrix9d h;
  for (int col = 0; col < 9; ++col) {
    Eigen::Matrix3d df = Eigen::Matrix3d::Zero();
    df(col) = 1.0;
    const Eigen::Matrix3d dp = m.mu() * df + a * f_inv_t * df.transpose() * f_inv_t +
                               b * f_inv_t.cwiseProduct(df).sum() * f_inv_t;
    h.col(col) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(dp.data());
  }
  return h;
}

// A well-shaped random tet of edge ~size: a regular tet, randomly rotated and perturbed by
// 10 % of its size, positively oriented.
inline TetPositions RandomRestTet(double size, std::mt19937& rng) {
  TetPositions x;
  x << 1, -1, -1, 1,  //
      1, -1, 1, -1,   //
      1, 1, -1, -1;
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  const Eigen::Matrix3d r = RandomRotation(rng);
  for (int v = 0; v < 4; ++v) {
    x.col(v) = r * x.col(v) * (0.5 * size);
    for (int c = 0; c < 3; ++c) x(c, v) += jitter(rng) * size;
  }
  if (SignedTetVolume(x) < 0) x.col(2).swap(x.col(3));
  return x;
}

// A tet's 12 coordinates (corner-major) as a vector, and back.
inline Eigen::Map<const TetPositions> AsPositions(const Eigen::VectorXd& x) {
  return Eigen::Map<const TetPositions>(x.data());
}
inline Eigen::VectorXd AsVector(const TetPositions& x) {
  return Eigen::Map<const Eigen::Matrix<double, 12, 1>>(x.data());
}

}  // namespace ergo::material_testing
