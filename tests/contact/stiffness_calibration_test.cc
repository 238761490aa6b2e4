// Stiffness calibration on analytic "equilibrium" models whose answer is known: the
// fixed-contact-set model pen = W/(2kn) ∝ 1/k and a Hertz-like pen ∝ k^(−2/3), plus
// failing, flat and discontinuous models that must stop with a reason.
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "ergo/contact/stiffness_calibration.h"

namespace ergo {
namespace {

constexpr double kTarget = 3e-4;  // the paper's 0.3 mm

TEST(Contact, CalibrationHitsTheTargetForPenetrationInverseToStiffness) {
  // n = 40 contact vertices share a W = 700 N load: 2k·pen·n = W.
  int calls = 0;
  const auto model = [&](double k) -> std::optional<double> {
    ++calls;
    return 700.0 / (2 * k * 40);
  };
  const CalibrationResult result = CalibrateStiffness(model);
  EXPECT_TRUE(result.converged) << result.BriefReport();
  EXPECT_EQ(result.evaluations, calls);
  // α = 1 is exact here, so the first Newton step in log k lands on the answer.
  EXPECT_EQ(result.evaluations, 2);
  EXPECT_NEAR(result.stiffness, 700.0 / (2 * 40 * kTarget), 1e-6 * result.stiffness);
  EXPECT_NEAR(result.penetration, kTarget, 1e-9);
  EXPECT_NE(result.BriefReport().find("converged"), std::string::npos);
}

TEST(Contact, CalibrationHitsTheTargetForAHertzLikeModel) {
  // A contact patch that grows as k drops: pen ∝ k^(−2/3).
  for (double initial : {1e2, 1e4, 1e8}) {
    const auto model = [](double k) -> std::optional<double> {
      return 0.9 * std::pow(k, -2.0 / 3.0);
    };
    CalibrationOptions options;
    options.initial_stiffness = initial;
    const CalibrationResult result = CalibrateStiffness(model, kTarget, options);
    EXPECT_TRUE(result.converged) << result.BriefReport();
    EXPECT_LE(result.evaluations, 4) << result.BriefReport();
    EXPECT_LE(std::abs(result.penetration - kTarget), 0.05 * kTarget);
    EXPECT_NEAR(*model(result.stiffness), result.penetration, 1e-15);
  }
  // A tighter tolerance is honoured.
  CalibrationOptions tight;
  tight.relative_tolerance = 1e-6;
  const CalibrationResult result = CalibrateStiffness(
      [](double k) -> std::optional<double> { return 0.9 * std::pow(k, -2.0 / 3.0); }, 2e-4, tight);
  EXPECT_TRUE(result.converged) << result.BriefReport();
  EXPECT_NEAR(result.penetration, 2e-4, 2e-10);
}

TEST(Contact, CalibrationBacksOffWhenTheEquilibriumFails) {
  // pen ∝ k^(−2): the first α = 1 step overshoots into stiffnesses where the solve fails.
  int failures = 0;
  const double answer = std::sqrt(1e3 / kTarget);
  const auto model = [&](double k) -> std::optional<double> {
    if (k > 3 * answer) {
      ++failures;
      return std::nullopt;
    }
    return 1e3 / (k * k);
  };
  CalibrationOptions options;
  options.initial_stiffness = 10;
  const CalibrationResult result = CalibrateStiffness(model, kTarget, options);
  EXPECT_GT(failures, 0);
  EXPECT_TRUE(result.converged) << result.BriefReport();
  EXPECT_LE(result.evaluations, options.max_evaluations);
}

TEST(Contact, CalibrationReportsWhyItStopped) {
  CalibrationOptions options;
  options.max_evaluations = 8;
  // The first solve fails: nothing to back off to.
  CalibrationResult result = CalibrateStiffness(
      [](double) -> std::optional<double> { return std::nullopt; }, kTarget, options);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.evaluations, 1);
  EXPECT_NE(result.message.find("failed"), std::string::npos) << result.message;

  // Penetration independent of k: it never gets there, within the cap.
  int calls = 0;
  result = CalibrateStiffness(
      [&](double) -> std::optional<double> {
        ++calls;
        return 1e-3;
      },
      kTarget, options);
  EXPECT_FALSE(result.converged);
  EXPECT_LE(calls, options.max_evaluations);
  EXPECT_FALSE(result.message.empty());
  EXPECT_NE(result.BriefReport().find("not converged"), std::string::npos);

  // The penetration jumps over the target (the contact set changes): the bracket collapses
  // and the best k is returned.
  options.max_evaluations = 100;
  result = CalibrateStiffness(
      [](double k) -> std::optional<double> { return k < 1e5 ? 2 * kTarget : 0.5 * kTarget; },
      kTarget, options);
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.message.find("bracket"), std::string::npos) << result.message;
  EXPECT_LT(result.evaluations, 100);
  EXPECT_NEAR(std::log(result.stiffness), std::log(1e5), 1e-6);
}

}  // namespace
}  // namespace ergo
