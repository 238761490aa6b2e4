// The rest-shape derivatives (ergo/material/rest_shape_derivative.h) against central
// differences of the element's energy and forces recomputed from perturbed rest positions,
// along random directions, the analytic gradient's own direction and every coordinate.
#include "ergo/material/rest_shape_derivative.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

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

// As the position derivatives' tests (tet_element_test.cc): central differences over a
// step sweep reach 1e-8–1e-7 of the natural scale; 1e-6 leaves room without hiding a wrong
// term, which is O(1) of the scale.
constexpr double kFdTolerance = 1e-6;

void CheckRestDerivatives(Regime regime, double size, unsigned seed) {
  double worst_energy = 0, worst_force = 0;
  // (nu, alpha): neo-Hookean at three nu, and the heel pad's stiffening law (README §1a).
  for (const auto& [nu, alpha] : {std::pair{0.0, 2.0}, {0.3, 2.0}, {0.45, 2.0}, {0.45, 6.82}}) {
    NeoHookeanParameters parameters;
    parameters.youngs_modulus = 5e4;
    parameters.poisson_ratio = nu;
    parameters.stiffening_exponent = alpha;
    const NeoHookean material(parameters);
    std::mt19937 rng(seed);
    for (int sample = 0; sample < 6; ++sample) {
      const TetPositions rest = RandomRestTet(size, rng);
      const Eigen::Vector3d sigma =
          StretchesFor(regime, parameters.inversion_threshold, sample, rng);
      // Deformed relative to another random tet, so that x is not an affine image of X.
      const TetPositions x = (DeformationWithStretches(sigma, rng) * rest).colwise() +
                             Eigen::Vector3d(0.1, -0.2, 0.3) * size;
      const TetRestData data = *ComputeTetRestData(rest);
      const double force_scale = material.mu() * data.volume * data.dm_inverse.norm();
      const double stiffness_scale = force_scale * data.dm_inverse.norm();
      const std::vector<double> steps = testing::StepSweep(1e-3 * size, 7);
      std::string report;
      const double energy_error = testing::WorstGradientError(
          [&](const Eigen::VectorXd& rest_vector) {
            return ElementEnergy(material, *ComputeTetRestData(AsPositions(rest_vector)), x);
          },
          ElementEnergyRestGradient(material, rest, x), AsVector(rest), force_scale, steps, 6, 12,
          seed + sample, &report);
      EXPECT_LE(energy_error, kFdTolerance) << RegimeName(regime) << "\n" << report;
      const double force_error = testing::WorstJacobianError(
          [&](const Eigen::VectorXd& rest_vector) {
            return Eigen::VectorXd(
                ElementGradient(material, *ComputeTetRestData(AsPositions(rest_vector)), x));
          },
          ElementForceRestJacobian(material, rest, x), AsVector(rest), stiffness_scale, steps, 6,
          12, seed + sample, &report);
      EXPECT_LE(force_error, kFdTolerance) << RegimeName(regime) << "\n" << report;
      worst_energy = std::max(worst_energy, energy_error);
      worst_force = std::max(worst_force, force_error);
    }
  }
  std::printf("[ FD       ] rest shape (edge %g m), %s: dE/dX %.2e, df/dX %.2e\n", size,
              RegimeName(regime).c_str(), worst_energy, worst_force);
}

TEST(RestShape, DerivativesMatchFiniteDifferencesAtRandomF) {
  CheckRestDerivatives(Regime::kRandom, 1.0, 501);
  CheckRestDerivatives(Regime::kRandom, 0.01, 502);
}
TEST(RestShape, DerivativesMatchFiniteDifferencesNearInversion) {
  CheckRestDerivatives(Regime::kNearThreshold, 0.01, 503);
}
TEST(RestShape, DerivativesMatchFiniteDifferencesWhenInverted) {
  CheckRestDerivatives(Regime::kInverted, 0.01, 504);
}

TEST(RestShape, VolumeGradientMatchesFiniteDifferences) {
  std::mt19937 rng(505);
  const TetPositions rest = RandomRestTet(0.02, rng);
  std::string report;
  const double error = testing::WorstGradientError(
      [](const Eigen::VectorXd& r) { return SignedTetVolume(AsPositions(r)); },
      TetVolumeRestGradient(rest), AsVector(rest), 0.02 * 0.02, testing::StepSweep(2e-5, 6), 6, 12,
      505, &report);
  EXPECT_LE(error, kFdTolerance) << report;
}

// Translating or (for this isotropic material) rotating the rest shape leaves F's invariants
// and V unchanged: the energy's rest gradient is orthogonal to both motions, and the forces
// do not change under a rest translation.
TEST(RestShape, RigidMotionsOfTheRestShapeChangeNoEnergy) {
  std::mt19937 rng(506);
  const NeoHookean material(NeoHookeanParameters{});
  const TetPositions rest = RandomRestTet(0.02, rng);
  const TetPositions x = DeformationWithStretches({1.2, 0.8, 0.9}, rng) * rest;
  const Vector12d energy_gradient = ElementEnergyRestGradient(material, rest, x);
  const Matrix12d rest_jacobian = ElementForceRestJacobian(material, rest, x);
  ASSERT_GT(energy_gradient.norm(), 0);
  for (int c = 0; c < 3; ++c) {
    Vector12d translation = Vector12d::Zero(), rotation = Vector12d::Zero();
    for (int v = 0; v < 4; ++v) {
      translation[3 * v + c] = 1;
      rotation.segment<3>(3 * v) = Eigen::Vector3d::Unit(c).cross(Eigen::Vector3d(rest.col(v)));
    }
    EXPECT_LE(std::abs(energy_gradient.dot(translation)), 1e-12 * energy_gradient.norm());
    EXPECT_LE(std::abs(energy_gradient.dot(rotation)), 1e-12 * energy_gradient.norm() * 0.02);
    EXPECT_LE((rest_jacobian * translation).norm(), 1e-12 * rest_jacobian.norm());
  }
}

}  // namespace
}  // namespace ergo
