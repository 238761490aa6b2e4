#include "ergo/equilibrium/golden_section.h"

#include <cmath>

#include <gtest/gtest.h>

namespace ergo {
namespace {

TEST(Equilibrium, GoldenSectionAcceptsTheFullStepWhenItDecreasesEnough) {
  // φ(η) = η² − 2η (Newton-like: minimiser at 1, φ'(0) = −2): φ(1) = −1 ≤ 1e-4·(−2).
  int calls = 0;
  auto phi = [&](double eta) {
    ++calls;
    return eta * eta - 2 * eta;
  };
  const GoldenSectionResult r = GoldenSectionSearch(phi, -2.0, {});
  EXPECT_EQ(r.step, 1.0);
  EXPECT_EQ(r.evaluations, 1);
  EXPECT_EQ(calls, 1);
}

TEST(Equilibrium, GoldenSectionFindsTheMinimiserInsideTheUnitInterval) {
  // φ(η) = (η − 0.3)² − 0.09: minimiser 0.3, φ(1) = 0.4 > 0 rejects the full step.
  auto phi = [](double eta) { return (eta - 0.3) * (eta - 0.3) - 0.09; };
  GoldenSectionOptions options;
  options.relative_width = 1e-3;
  options.max_evaluations = 60;
  const GoldenSectionResult r = GoldenSectionSearch(phi, -0.6, options);
  EXPECT_NEAR(r.step, 0.3, 1e-3);
  EXPECT_LT(r.value, 0);
}

TEST(Equilibrium, InterpolatedLineSearchTakesTheQuadraticsMinimiserInTwoTrials) {
  // φ(η) = (η − 0.3)² − 0.09 is its own quadratic model: φ(1) = 0.4, φ'(0) = −0.6 give
  // η = 0.6 / (2·(0.4 + 0.6)) = 0.3 exactly, which passes Armijo.
  auto phi = [](double eta) { return (eta - 0.3) * (eta - 0.3) - 0.09; };
  GoldenSectionOptions options;
  options.interpolate = true;
  const GoldenSectionResult r = GoldenSectionSearch(phi, -0.6, options);
  EXPECT_EQ(r.evaluations, 2);
  EXPECT_NEAR(r.step, 0.3, 1e-15);
  EXPECT_NEAR(r.value, -0.09, 1e-15);
}

TEST(Equilibrium, InterpolatedLineSearchFallsBackToGoldenSectionsWhenTheModelFails) {
  // A stiff wall at η = 0.05 behind a linear decrease: the quadratic's step (clamped at
  // 0.1) lands beyond the wall, so the search shrinks and reduces as without the model.
  auto phi = [](double eta) { return eta < 0.05 ? -eta : -0.05 + 1e6 * (eta - 0.05); };
  GoldenSectionOptions options;
  options.interpolate = true;
  options.max_evaluations = 60;
  const GoldenSectionResult r = GoldenSectionSearch(phi, -1.0, options);
  EXPECT_GT(r.evaluations, 2);
  EXPECT_NEAR(r.step, 0.05, 1e-3);  // the reduction stops at a bracket 1 % of the step wide
  // An undefined φ(1) (an inverted element) halves the step instead.
  auto undefined = [](double eta) { return eta > 0.6 ? NAN : eta * eta - eta; };
  const GoldenSectionResult h = GoldenSectionSearch(undefined, -1.0, options);
  EXPECT_EQ(h.evaluations, 2);
  EXPECT_EQ(h.step, 0.5);
}

TEST(Equilibrium, GoldenSectionShrinksPastAnInfiniteTrial) {
  // Beyond η = 0.05 the energy is undefined (an inverted element): the search must shrink.
  auto phi = [](double eta) { return eta > 0.05 ? NAN : -eta; };
  const GoldenSectionResult r = GoldenSectionSearch(phi, -1.0, {});
  EXPECT_GT(r.step, 0);
  EXPECT_LE(r.step, 0.05);
}

TEST(Equilibrium, GoldenSectionExpandsInFreeFall) {
  // Linear decrease until contact at η = 40, then a stiff rise: the expansion walks out
  // and the golden phase settles near the kink.
  auto phi = [](double eta) { return eta < 40 ? -eta : -40 + 1e3 * (eta - 40) * (eta - 40); };
  GoldenSectionOptions options;
  options.expand = true;
  options.max_evaluations = 60;
  const GoldenSectionResult r = GoldenSectionSearch(phi, -1.0, options);
  EXPECT_NEAR(r.step, 40.0, 0.5);
}

TEST(Equilibrium, GoldenSectionReportsNoDecrease) {
  auto phi = [](double eta) { return eta; };  // not a descent direction after all
  const GoldenSectionResult r = GoldenSectionSearch(phi, -1.0, {});
  EXPECT_EQ(r.step, 0.0);
}

TEST(Equilibrium, GoldenSectionFlagsRoundOffLevelChanges) {
  auto phi = [](double eta) { return 1e-18 * eta; };
  GoldenSectionOptions options;
  options.noise = 1e-15;
  const GoldenSectionResult r = GoldenSectionSearch(phi, -1e-20, options);
  EXPECT_TRUE(r.undecidable);
  EXPECT_EQ(r.step, 1.0);
}

}  // namespace
}  // namespace ergo
