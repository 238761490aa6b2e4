#include "ergo/material/tet_element.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "ergo/mesh/primitives.h"
#include "tests/material/material_test_util.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using material_testing::AsPositions;
using material_testing::AsVector;
using material_testing::DeformationWithStretches;
using material_testing::RandomRestTet;
using material_testing::RandomRotation;
using material_testing::Regime;
using material_testing::RegimeName;
using material_testing::StretchesFor;

constexpr double kFdTolerance = 1e-6;  // justified in neo_hookean_test.cc
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// x_v = F X_v + t: the deformed tet whose deformation gradient is exactly F.
TetPositions Deform(const TetPositions& rest, const Eigen::Matrix3d& f, const Eigen::Vector3d& t) {
  return (f * rest).colwise() + t;
}

// d vec(F) / dx as a dense 9x12 matrix, for checking the structured maps.
Eigen::Matrix<double, 9, 12> DenseDeformationJacobian(const TetRestData& rest) {
  Eigen::Matrix<double, 9, 12> d = Eigen::Matrix<double, 9, 12>::Zero();
  Eigen::Matrix<double, 4, 3> g;
  g.bottomRows<3>() = rest.dm_inverse;
  g.row(0) = -rest.dm_inverse.colwise().sum();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int v = 0; v < 4; ++v) d(a + 3 * b, 3 * v + a) = g(v, b);
  return d;
}

TEST(Material, RestDataRefusesDegenerateAndInvertedTets) {
  TetPositions rest;
  rest << 0, 1, 0, 0,  //
      0, 0, 1, 0,      //
      0, 0, 0, 1;
  const std::optional<TetRestData> good = ComputeTetRestData(rest);
  ASSERT_TRUE(good.has_value());
  EXPECT_NEAR(good->volume, 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(good->dm_inverse.isIdentity(1e-15));
  EXPECT_FALSE(ComputeTetRestData(rest, 0.2).has_value());  // below min_volume

  TetPositions inverted = rest;
  inverted.col(1).swap(inverted.col(2));
  EXPECT_LT(SignedTetVolume(inverted), 0);
  EXPECT_FALSE(ComputeTetRestData(inverted).has_value());

  TetPositions flat = rest;
  flat(2, 3) = 0;  // all four in the plane z = 0
  EXPECT_FALSE(ComputeTetRestData(flat).has_value());
  TetPositions collapsed = TetPositions::Zero();
  EXPECT_FALSE(ComputeTetRestData(collapsed).has_value());
}

TEST(Material, DeformationGradientOfAnAffineMapIsItsMatrix) {
  std::mt19937 rng(3);
  const TetPositions rest = RandomRestTet(0.01, rng);
  const TetRestData data = *ComputeTetRestData(rest);
  const Eigen::Matrix3d f = DeformationWithStretches({1.3, 0.7, -0.2}, rng);
  EXPECT_LE((DeformationGradient(data, Deform(rest, f, {0.1, -2, 3})) - f).norm(), 1e-12);
}

TEST(Material, StructuredMapsMatchDensePullback) {
  // The Kronecker-structured 9 -> 12 maps equal V D^T P and V D^T H9 D.
  std::mt19937 rng(4);
  std::normal_distribution<double> normal;
  for (int sample = 0; sample < 10; ++sample) {
    const TetRestData data = *ComputeTetRestData(RandomRestTet(0.02, rng));
    const Eigen::Matrix<double, 9, 12> d = DenseDeformationJacobian(data);
    Eigen::Matrix3d p;
    Matrix9d h;
    for (int i = 0; i < 9; ++i) p(i) = normal(rng);
    for (int i = 0; i < 81; ++i) h(i) = normal(rng);
    h = (h + h.transpose()).eval();
    const Vector12d gradient =
        data.volume * d.transpose() * Eigen::Map<const Eigen::Matrix<double, 9, 1>>(p.data());
    const Matrix12d hessian = data.volume * d.transpose() * h * d;
    EXPECT_LE((ElementGradientFromStress(data, p) - gradient).norm(), 1e-13 * gradient.norm());
    EXPECT_LE((ElementHessianFromStressDerivative(data, h) - hessian).norm(),
              1e-13 * hessian.norm());
  }
}

// Element energy -> gradient -> Hessian in positions (12 DOFs) in one regime.
void CheckElementDerivatives(Regime regime, double size, unsigned seed) {
  double worst_gradient = 0, worst_hessian = 0;
  // The stiffening law (README §1a) at nu = 0.49: alpha 6.82, the heel pad's.
  for (const double nu : {0.3, 0.45, 0.49}) {
    NeoHookeanParameters parameters;
    parameters.poisson_ratio = nu;
    parameters.compression_resistance = nu == 0.3 ? 1000.0 : 1.0;
    parameters.stiffening_exponent = nu == 0.49 ? 6.82 : 2.0;
    const NeoHookean material(parameters);
    std::mt19937 rng(seed);
    for (int sample = 0; sample < 8; ++sample) {
      const TetPositions rest = RandomRestTet(size, rng);
      const TetRestData data = *ComputeTetRestData(rest);
      const Eigen::Vector3d sigma =
          StretchesFor(regime, parameters.inversion_threshold, sample, rng);
      const TetPositions x =
          Deform(rest, DeformationWithStretches(sigma, rng), Eigen::Vector3d(0.1, 0.2, 0.3));
      double energy;
      Vector12d gradient;
      Matrix12d hessian;
      EvaluateElement(material, data, x, HessianKind::kExact, &energy, &gradient, &hessian);
      // Natural scales: force mu V |Dm^-1| and stiffness mu V |Dm^-1|^2.
      const double force_scale = material.mu() * data.volume * data.dm_inverse.norm();
      const double stiffness_scale = force_scale * data.dm_inverse.norm();
      const std::vector<double> steps = testing::StepSweep(1e-2 * size, 7);
      std::string report;
      const double gradient_error = testing::WorstGradientError(
          [&](const Eigen::VectorXd& y) { return ElementEnergy(material, data, AsPositions(y)); },
          gradient, AsVector(x), force_scale, steps, 6, 12, seed + sample, &report);
      EXPECT_LE(gradient_error, kFdTolerance)
          << RegimeName(regime) << " sigma " << sigma.transpose() << "\n"
          << report;
      const double hessian_error = testing::WorstJacobianError(
          [&](const Eigen::VectorXd& y) {
            return Eigen::VectorXd(ElementGradient(material, data, AsPositions(y)));
          },
          hessian, AsVector(x), stiffness_scale, steps, 6, 12, seed + sample, &report);
      EXPECT_LE(hessian_error, kFdTolerance)
          << RegimeName(regime) << " sigma " << sigma.transpose() << "\n"
          << report;
      worst_gradient = std::max(worst_gradient, gradient_error);
      worst_hessian = std::max(worst_hessian, hessian_error);
    }
  }
  std::printf(
      "[ FD       ] element (edge %g m), %s: energy -> gradient %.2e, gradient -> Hessian "
      "%.2e\n",
      size, RegimeName(regime).c_str(), worst_gradient, worst_hessian);
}

TEST(Material, ElementDerivativesMatchFiniteDifferencesAtRandomF) {
  CheckElementDerivatives(Regime::kRandom, 1.0, 301);
  CheckElementDerivatives(Regime::kRandom, 0.01, 302);
}
TEST(Material, ElementDerivativesMatchFiniteDifferencesAtRepeatedStretches) {
  CheckElementDerivatives(Regime::kRepeated, 1.0, 303);
}
TEST(Material, ElementDerivativesMatchFiniteDifferencesNearInversion) {
  CheckElementDerivatives(Regime::kNearThreshold, 1.0, 304);
}
TEST(Material, ElementDerivativesMatchFiniteDifferencesBelowThreshold) {
  CheckElementDerivatives(Regime::kBelowThreshold, 1.0, 305);
  CheckElementDerivatives(Regime::kBelowThreshold, 0.01, 306);
}
TEST(Material, ElementDerivativesMatchFiniteDifferencesWhenInverted) {
  CheckElementDerivatives(Regime::kInverted, 1.0, 307);
}

TEST(Material, CombinedElementEvaluationMatchesSeparateCalls) {
  std::mt19937 rng(8);
  const NeoHookean material(NeoHookeanParameters{});
  const TetPositions rest = RandomRestTet(0.02, rng);
  const TetRestData data = *ComputeTetRestData(rest);
  const TetPositions x =
      Deform(rest, DeformationWithStretches({1.1, 0.05, -0.3}, rng), Eigen::Vector3d::Zero());
  for (HessianKind kind : {HessianKind::kExact, HessianKind::kProjectedPsd}) {
    double energy;
    Vector12d gradient;
    Matrix12d hessian;
    EvaluateElement(material, data, x, kind, &energy, &gradient, &hessian);
    EXPECT_EQ(energy, ElementEnergy(material, data, x));
    EXPECT_EQ(gradient, ElementGradient(material, data, x));
    EXPECT_EQ(hessian, ElementHessian(material, data, x, kind));
    EXPECT_EQ(energy, data.volume * material.EnergyDensity(DeformationGradient(data, x)));
    // The principal-frame element assembly equals the pullback of dP/dF.
    const Matrix12d pulled_back = ElementHessianFromStressDerivative(
        data, material.StressDerivative(DeformationGradient(data, x), kind));
    EXPECT_LE((hessian - pulled_back).norm(), 1e-13 * pulled_back.norm());
  }
}

TEST(Material, ProjectedElementHessianIsPositiveSemiDefinite) {
  double worst = 0;
  std::mt19937 rng(9);
  for (const double nu : {0.3, 0.45, 0.49}) {
    NeoHookeanParameters parameters;
    parameters.poisson_ratio = nu;
    parameters.stiffening_exponent = nu == 0.49 ? 6.82 : 2.0;  // README §1a
    const NeoHookean material(parameters);
    for (Regime regime : {Regime::kRandom, Regime::kRepeated, Regime::kNearThreshold,
                          Regime::kBelowThreshold, Regime::kInverted}) {
      for (int sample = 0; sample < 10; ++sample) {
        const TetPositions rest = RandomRestTet(0.01, rng);
        const TetRestData data = *ComputeTetRestData(rest);
        const TetPositions x =
            Deform(rest,
                   DeformationWithStretches(
                       StretchesFor(regime, parameters.inversion_threshold, sample, rng), rng),
                   Eigen::Vector3d::Zero());
        const Matrix12d exact = ElementHessian(material, data, x, HessianKind::kExact);
        const Matrix12d projected = ElementHessian(material, data, x, HessianKind::kProjectedPsd);
        EXPECT_TRUE(projected.allFinite());
        Eigen::SelfAdjointEigenSolver<Matrix12d> eigen(projected);
        const double relative_min =
            eigen.eigenvalues().minCoeff() / eigen.eigenvalues().cwiseAbs().maxCoeff();
        EXPECT_GE(relative_min, -1e-12) << RegimeName(regime);
        worst = std::min(worst, relative_min);
        // Translations are in the null space of both (the energy ignores them).
        for (int c = 0; c < 3; ++c) {
          Vector12d translation = Vector12d::Zero();
          for (int v = 0; v < 4; ++v) translation(3 * v + c) = 1;
          EXPECT_LE((projected * translation).norm(), 1e-12 * projected.norm());
          EXPECT_LE((exact * translation).norm(), 1e-12 * exact.norm());
        }
      }
    }
  }
  std::printf("[ PSD      ] most negative eigenvalue / norm of projected 12x12: %.1e\n", worst);
}

// Sum of element gradients of a whole tet mesh at deformed positions x (#V x 3).
Vertices AssembleGradient(const NeoHookean& material, const TetMesh& mesh, const Vertices& x,
                          double* energy) {
  Vertices gradient = Vertices::Zero(x.rows(), 3);
  *energy = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    TetPositions rest, deformed;
    for (int v = 0; v < 4; ++v) {
      rest.col(v) = mesh.vertices.row(mesh.tets(t, v)).transpose();
      deformed.col(v) = x.row(mesh.tets(t, v)).transpose();
    }
    const TetRestData data = *ComputeTetRestData(rest);
    double element_energy;
    Vector12d element_gradient;
    EvaluateElement(material, data, deformed, HessianKind::kExact, &element_energy,
                    &element_gradient, nullptr);
    *energy += element_energy;
    for (int v = 0; v < 4; ++v) {
      gradient.row(mesh.tets(t, v)) += element_gradient.segment<3>(3 * v).transpose();
    }
  }
  return gradient;
}

bool IsInterior(const Eigen::RowVector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p(c) - lo(c)) < 1e-12 || std::abs(p(c) - hi(c)) < 1e-12) return false;
  }
  return true;
}

TEST(Material, PatchTestUniformDeformationGivesAnalyticStressEverywhere) {
  // A cube of tets under x = A X + b: every element has F = A and the reference-form P(A),
  // and the interior vertices feel no net force (the stress field is divergence-free).
  const Eigen::Vector3d lo(0, 0, 0), hi(0.1, 0.1, 0.1);
  const TetMesh mesh = MakeTetGrid(lo, hi, {3, 3, 3});
  std::mt19937 rng(12);
  NeoHookeanParameters parameters;
  parameters.compression_resistance = 1000.0;  // make psi_c visible in P
  const NeoHookean material(parameters);
  int interior = 0;
  for (const Eigen::Vector3d& sigma : {Eigen::Vector3d(1.3, 0.9, 0.6),   // compressed, J < 1
                                       Eigen::Vector3d(1.4, 1.2, 1.05),  // stretched
                                       Eigen::Vector3d(0.8, 0.5, 0.15)}) {
    const Eigen::Matrix3d a = DeformationWithStretches(sigma, rng);
    const Eigen::Vector3d b(0.3, -0.1, 2.0);
    const Vertices x = ((mesh.vertices * a.transpose()).rowwise() + b.transpose()).eval();
    const Eigen::Matrix3d p_reference = material_testing::ReferencePiola(material, a);
    double worst_stress = 0;
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
      TetPositions rest, deformed;
      for (int v = 0; v < 4; ++v) {
        rest.col(v) = mesh.vertices.row(mesh.tets(t, v)).transpose();
        deformed.col(v) = x.row(mesh.tets(t, v)).transpose();
      }
      const TetRestData data = *ComputeTetRestData(rest);
      const Eigen::Matrix3d f = DeformationGradient(data, deformed);
      EXPECT_LE((f - a).norm(), 1e-13 * a.norm());
      worst_stress = std::max(worst_stress,
                              (material.FirstPiola(f) - p_reference).norm() / p_reference.norm());
    }
    EXPECT_LE(worst_stress, 1e-12);
    double energy;
    const Vertices gradient = AssembleGradient(material, mesh, x, &energy);
    EXPECT_NEAR(energy, 1e-3 * material_testing::ReferenceEnergy(material, a),
                1e-12 * std::abs(energy));
    // One element's vertex force is ~ V |P| |Dm^-1| ~ |P| h^2; the interior sums of ~24
    // such terms cancel to round-off.
    const double h = 0.1 / 3;
    const double force_scale = p_reference.norm() * h * h;
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      if (!IsInterior(mesh.vertices.row(v), lo, hi)) continue;
      ++interior;
      EXPECT_LE(gradient.row(v).norm(), 1e-12 * force_scale) << "vertex " << v;
    }
    // Total force on the body is zero (translation invariance).
    EXPECT_LE(gradient.colwise().sum().norm(), 1e-12 * force_scale);
  }
  EXPECT_EQ(interior, 3 * 8);
}

TEST(Material, RigidMotionGivesZeroEnergyAndForces) {
  // x = R X + b for a random rotation: F = R, sigma = 1 up to a few ulps, and psi and P are
  // linear in sigma - 1 with moduli <= 2 mu + 3 lambda, so |psi| and |P| are round-off:
  // we allow 100 eps (2 mu + 3 lambda), i.e. ~1e-14 of the material's stiffness.
  const TetMesh mesh = MakeTetGrid({0, 0, 0}, {0.05, 0.08, 0.1}, {3, 4, 5});
  std::mt19937 rng(13);
  for (const double nu : {0.3, 0.45, 0.49}) {
    NeoHookeanParameters parameters;
    parameters.poisson_ratio = nu;
    const NeoHookean material(parameters);
    const double stress_tolerance = 100 * kEpsilon * (2 * material.mu() + 3 * material.lambda());
    for (int sample = 0; sample < 5; ++sample) {
      const Eigen::Matrix3d r = RandomRotation(rng);
      const Eigen::Vector3d b(0.5 * sample, -1.0, 0.25);
      const Vertices x = ((mesh.vertices * r.transpose()).rowwise() + b.transpose()).eval();
      double energy;
      const Vertices gradient = AssembleGradient(material, mesh, x, &energy);
      const double volume = 0.05 * 0.08 * 0.1;
      EXPECT_LE(std::abs(energy), stress_tolerance * volume);
      // Per vertex at most 24 elements, each V |P| |Dm^-1| ~ |P| h^2 with h = 1/60 m.
      const double force_tolerance = 24 * stress_tolerance * 3 * (0.02 * 0.02);
      EXPECT_LE(gradient.rowwise().norm().maxCoeff(), force_tolerance);
      if (sample == 0) {
        std::printf("[ RIGID    ] nu %.2f: |E| = %.1e J (tol %.1e), max |f| = %.1e N (tol %.1e)\n",
                    nu, std::abs(energy), stress_tolerance * volume,
                    gradient.rowwise().norm().maxCoeff(), force_tolerance);
      }
    }
  }
}

TEST(Material, EnergyScalesWithRestVolume) {
  // Scaling rest and deformed shapes by s keeps F: E ~ s^3, gradient ~ s^2, Hessian ~ s.
  std::mt19937 rng(14);
  const NeoHookean material(NeoHookeanParameters{});
  const TetPositions rest = RandomRestTet(1.0, rng);
  const Eigen::Matrix3d f = DeformationWithStretches({1.2, 0.4, -0.05}, rng);
  const TetPositions x = Deform(rest, f, Eigen::Vector3d::Zero());
  double energy;
  Vector12d gradient;
  Matrix12d hessian;
  EvaluateElement(material, *ComputeTetRestData(rest), x, HessianKind::kProjectedPsd, &energy,
                  &gradient, &hessian);
  EXPECT_NEAR(energy, SignedTetVolume(rest) * material.EnergyDensity(f), 1e-12 * energy);
  for (const double s : {1e-3, 0.01, 7.0}) {
    double scaled_energy;
    Vector12d scaled_gradient;
    Matrix12d scaled_hessian;
    EvaluateElement(material, *ComputeTetRestData(s * rest), s * x, HessianKind::kProjectedPsd,
                    &scaled_energy, &scaled_gradient, &scaled_hessian);
    EXPECT_NEAR(scaled_energy, s * s * s * energy, 1e-12 * s * s * s * energy);
    EXPECT_LE((scaled_gradient - s * s * gradient).norm(), 1e-12 * s * s * gradient.norm());
    EXPECT_LE((scaled_hessian - s * hessian).norm(), 1e-12 * s * hessian.norm());
  }
}

TEST(Material, DegenerateElementsGiveFiniteEnergyForcesAndHessians) {
  // Collapsed (all vertices at one point, on a line, in a plane) and inverted tets.
  std::mt19937 rng(15);
  const NeoHookean material(NeoHookeanParameters{});
  const TetPositions rest = RandomRestTet(0.01, rng);
  const TetRestData data = *ComputeTetRestData(rest);
  std::vector<TetPositions> shapes;
  shapes.push_back(TetPositions::Zero());
  TetPositions line;
  for (int v = 0; v < 4; ++v) line.col(v) = Eigen::Vector3d(1, 2, 3) * (0.01 * v * v);
  shapes.push_back(line);
  TetPositions plane = rest;
  plane.row(2).setConstant(0.5);
  shapes.push_back(plane);
  TetPositions inverted = rest;
  inverted.col(0).swap(inverted.col(1));
  shapes.push_back(inverted);
  shapes.push_back(-rest);  // point reflection: F = -I
  for (const TetPositions& x : shapes) {
    for (HessianKind kind : {HessianKind::kExact, HessianKind::kProjectedPsd}) {
      double energy = NAN;
      Vector12d gradient;
      Matrix12d hessian;
      EvaluateElement(material, data, x, kind, &energy, &gradient, &hessian);
      EXPECT_TRUE(std::isfinite(energy)) << x;
      EXPECT_TRUE(gradient.allFinite()) << x;
      EXPECT_TRUE(hessian.allFinite()) << x;
    }
  }
}

}  // namespace
}  // namespace ergo
