// The layered indentation law against answers known without the code: the Hertz half-space
// by hand, the coefficients Dimitriadis et al. 2002 print for an incompressible layer, and
// its partial derivatives against central differences.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "ergo/calibration/layered_indentation.h"

namespace ergo {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(Calibration, HalfSpaceIsTheHertzLawComputedByHand) {
  // R = 5 mm, E = 50 kPa, ν = 0.5, δ = 1 mm: F = 4/3 · E/(1 − ν²) · √R · δ^{3/2}
  // = 4/3 · 66 666.7 Pa · 0.0707107 m^½ · 3.16228e-5 m^{3/2} = 0.198762 N.
  SphericalIndenter indenter;
  indenter.radius = 0.005;
  indenter.poisson_ratio = 0.5;
  const IndentationForce law = LayeredIndentationForce(indenter, 5e4, kInfinity, 0.001);
  EXPECT_NEAR(law.force, 0.198762, 1e-6);
  EXPECT_EQ(law.chi, 0);
  EXPECT_EQ(law.d_depth, 0);
  // F ∝ δ^{3/2}: ∂F/∂δ = 1.5 F/δ.
  EXPECT_NEAR(law.d_indentation, 1.5 * law.force / 0.001, 1e-9);
}

TEST(Calibration, IncompressibleLayerCoefficientsAreThePublishedOnes) {
  // Dimitriadis et al. 2002 for ν = 0.5: bonded 1 + 1.133χ + 1.283χ² + 0.769χ³ + 0.0975χ⁴,
  // sliding 1 + 0.884χ + 0.781χ² + 0.386χ³ + 0.0048χ⁴, printed to 3–4 digits. The general
  // formula gives −0.0974 for the bonded χ⁴ term (ergo/calibration/README.md), so that one
  // is checked in magnitude.
  const Eigen::Vector4d bonded = LayerCorrectionCoefficients(0.5, LayerBase::kBonded);
  EXPECT_NEAR(bonded[0], 1.133, 5e-4);
  EXPECT_NEAR(bonded[1], 1.283, 5e-4);
  EXPECT_NEAR(bonded[2], 0.769, 5e-4);
  EXPECT_NEAR(std::abs(bonded[3]), 0.0975, 5e-4);
  const Eigen::Vector4d sliding = LayerCorrectionCoefficients(0.5, LayerBase::kSliding);
  EXPECT_NEAR(sliding[0], 0.884, 5e-4);
  EXPECT_NEAR(sliding[1], 0.781, 5e-4);
  EXPECT_NEAR(sliding[2], 0.386, 5e-4);
  EXPECT_NEAR(sliding[3], 0.0048, 5e-5);
}

TEST(Calibration, AThinnerLayerIsStifferAndABondedOneStifferThanASlidingOne) {
  SphericalIndenter indenter;
  indenter.radius = 0.004;
  const double hertz = LayeredIndentationForce(indenter, 4e4, kInfinity, 0.002).force;
  double previous = hertz;
  for (double depth : {0.05, 0.02, 0.01, 0.006}) {
    const double force = LayeredIndentationForce(indenter, 4e4, depth, 0.002).force;
    EXPECT_GT(force, previous) << depth;
    previous = force;
  }
  SphericalIndenter sliding = indenter;
  sliding.base = LayerBase::kSliding;
  EXPECT_GT(LayeredIndentationForce(indenter, 4e4, 0.01, 0.002).force,
            LayeredIndentationForce(sliding, 4e4, 0.01, 0.002).force);
}

TEST(Calibration, IndentationLawDerivativesMatchCentralDifferences) {
  // Points across the law's range (χ from 0.05 to 1.4) for both bases and three ν. The law
  // is a polynomial in χ times δ^{3/2}: a step of 1e-6 relative leaves a central
  // difference's truncation and rounding near 1e-9 relative, so 1e-7 is a safe bound.
  for (LayerBase base : {LayerBase::kBonded, LayerBase::kSliding}) {
    for (double nu : {0.3, 0.45, 0.499}) {
      for (double depth : {0.004, 0.012, 0.03}) {
        for (double indentation : {2e-4, 1e-3, 3e-3}) {
          SphericalIndenter indenter;
          indenter.radius = 0.005;
          indenter.poisson_ratio = nu;
          indenter.base = base;
          const double youngs = 3.7e4;
          const IndentationForce law =
              LayeredIndentationForce(indenter, youngs, depth, indentation);
          auto force = [&](double e, double h, double d) {
            return LayeredIndentationForce(indenter, e, h, d).force;
          };
          const double step = 1e-6;
          const double d_youngs = (force(youngs * (1 + step), depth, indentation) -
                                   force(youngs * (1 - step), depth, indentation)) /
                                  (2 * step * youngs);
          const double d_depth = (force(youngs, depth * (1 + step), indentation) -
                                  force(youngs, depth * (1 - step), indentation)) /
                                 (2 * step * depth);
          const double d_indentation = (force(youngs, depth, indentation * (1 + step)) -
                                        force(youngs, depth, indentation * (1 - step))) /
                                       (2 * step * indentation);
          const std::string where = "nu " + std::to_string(nu) + " h " + std::to_string(depth) +
                                    " delta " + std::to_string(indentation);
          EXPECT_NEAR(law.d_youngs_modulus, d_youngs, 1e-7 * std::abs(d_youngs)) << where;
          EXPECT_NEAR(law.d_depth, d_depth, 1e-7 * std::abs(d_depth)) << where;
          EXPECT_NEAR(law.d_indentation, d_indentation, 1e-7 * std::abs(d_indentation)) << where;
          // Along the direction of the gradient itself (E, h, δ scaled to their values).
          const Eigen::Vector3d scale(youngs, depth, indentation);
          const Eigen::Vector3d gradient =
              Eigen::Vector3d(law.d_youngs_modulus, law.d_depth, law.d_indentation)
                  .cwiseProduct(scale);
          const Eigen::Vector3d direction = gradient.normalized();
          auto along = [&](double t) {
            const Eigen::Vector3d p = scale.cwiseProduct(Eigen::Vector3d::Ones() + t * direction);
            return force(p[0], p[1], p[2]);
          };
          const double directional = (along(step) - along(-step)) / (2 * step);
          EXPECT_NEAR(gradient.dot(direction), directional, 1e-7 * std::abs(directional)) << where;
        }
      }
    }
  }
}

}  // namespace
}  // namespace ergo
