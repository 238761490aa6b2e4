// Tissue calibration round trips: curves made by the law from a known modulus and depth come
// back as that modulus and depth (exactly without noise; within their reported standard
// errors with it), the residual's Jacobian passes ceres::GradientChecker, and curves that
// cannot determine what is asked say so.
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include "ergo/calibration/indentation_fit.h"

namespace ergo {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A heel-pad-like point: E = 45 kPa, h = 17 mm (Sun et al. 2011; ergo/body/README.md),
// a 10 mm sphere pressed 6 mm in 30 steps: χ up to 0.46.
constexpr double kYoungs = 4.5e4, kDepth = 0.017, kRadius = 0.010;

SphericalIndenter Indenter() {
  SphericalIndenter indenter;
  indenter.radius = kRadius;
  indenter.poisson_ratio = 0.45;
  return indenter;
}

struct Curve {
  std::vector<double> indentation, force;
};

// The law's curve plus noise·(peak force)·N(0, 1) on each reading (a load cell's noise,
// the same for every reading, as the fit's standard errors assume), from a fixed seed.
Curve MakeCurve(double youngs, double depth, double max_indentation, double noise,
                unsigned seed = 7) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  const double peak = LayeredIndentationForce(Indenter(), youngs, depth, max_indentation).force;
  Curve curve;
  for (int i = 0; i <= 30; ++i) {
    const double delta = max_indentation * i / 30;
    curve.indentation.push_back(delta);
    curve.force.push_back(LayeredIndentationForce(Indenter(), youngs, depth, delta).force +
                          noise * peak * normal(random));
  }
  return curve;
}

TEST(Calibration, NoiseFreeCurveGivesBackItsModulusAndDepth) {
  const Curve curve = MakeCurve(kYoungs, kDepth, 0.006, 0);
  IndentationFitOptions options;
  options.indenter = Indenter();
  options.fit_depth = true;
  options.depth = 0.04;  // a poor first guess
  const IndentationFit fit = FitIndentationCurve(curve.indentation, curve.force, options);
  ASSERT_TRUE(fit.converged) << fit.message;
  EXPECT_EQ(fit.readings, 30);  // the contact point itself is left out
  // Exact data: only the solver's tolerances (1e-12 in the parameters) remain.
  EXPECT_NEAR(fit.youngs_modulus, kYoungs, 1e-6 * kYoungs);
  EXPECT_NEAR(fit.depth, kDepth, 1e-6 * kDepth);
  EXPECT_LT(fit.relative_rms, 1e-9);
  EXPECT_NEAR(fit.max_chi, std::sqrt(kRadius * 0.006) / kDepth, 1e-6);
  EXPECT_FALSE(fit.depth_at_bound);
  // Its only note: 6 mm into 17 mm is beyond the small-strain range.
  EXPECT_NE(fit.message.find("δ/h = 0.35"), std::string::npos) << fit.message;
}

TEST(Calibration, NoisyCurvesAreRecoveredWithinTheirReportedStandardErrors) {
  // Noise of 1 % of the peak force. Over 20 seeds the misfit divided by the reported standard error
  // must look like a standard normal: each within 4 (a 6e-5 chance per draw), and the root mean
  // square between 0.5 and 1.6 (for 20 draws of N(0,1) it lies in [0.7, 1.3] with 95 %).
  double sum_youngs = 0, sum_depth = 0;
  const int seeds = 20;
  for (int seed = 1; seed <= seeds; ++seed) {
    const Curve curve = MakeCurve(kYoungs, kDepth, 0.006, 0.01, seed);
    IndentationFitOptions options;
    options.indenter = Indenter();
    options.fit_depth = true;
    const IndentationFit fit = FitIndentationCurve(curve.indentation, curve.force, options);
    ASSERT_TRUE(fit.converged) << seed << ": " << fit.message;
    ASSERT_GT(fit.youngs_modulus_stderr, 0);
    ASSERT_GT(fit.depth_stderr, 0);
    const double z_youngs = (fit.youngs_modulus - kYoungs) / fit.youngs_modulus_stderr;
    const double z_depth = (fit.depth - kDepth) / fit.depth_stderr;
    EXPECT_LT(std::abs(z_youngs), 4) << seed << ": " << DescribeFit(fit);
    EXPECT_LT(std::abs(z_depth), 4) << seed << ": " << DescribeFit(fit);
    // And useful: that noise on 30 readings leaves E within 10 % and h within 20 %.
    EXPECT_NEAR(fit.youngs_modulus, kYoungs, 0.10 * kYoungs) << seed;
    EXPECT_NEAR(fit.depth, kDepth, 0.20 * kDepth) << seed;
    sum_youngs += z_youngs * z_youngs;
    sum_depth += z_depth * z_depth;
  }
  std::cout << "RMS of misfit / standard error over " << seeds << " seeds: E "
            << std::sqrt(sum_youngs / seeds) << ", h " << std::sqrt(sum_depth / seeds) << "\n";
  for (double rms : {std::sqrt(sum_youngs / seeds), std::sqrt(sum_depth / seeds)}) {
    EXPECT_GT(rms, 0.5);
    EXPECT_LT(rms, 1.6);
  }
}

TEST(Calibration, AGivenDepthOrTheHalfSpaceFitsTheModulusAlone) {
  for (double depth : {kDepth, kInfinity}) {
    const Curve curve = MakeCurve(kYoungs, depth, 0.004, 0);
    IndentationFitOptions options;
    options.indenter = Indenter();
    options.depth = depth;
    const IndentationFit fit = FitIndentationCurve(curve.indentation, curve.force, options);
    ASSERT_TRUE(fit.converged) << fit.message;
    EXPECT_NEAR(fit.youngs_modulus, kYoungs, 1e-9 * kYoungs);
    EXPECT_EQ(fit.depth, depth);
    EXPECT_EQ(fit.depth_stderr, 0);
  }
  // Assuming a half-space for a 17 mm layer reads it too stiff: χ up to 0.37 puts the layer's
  // force 50 % above Hertz's at 4 mm, so the half-space modulus comes out well above 45 kPa.
  const Curve layer = MakeCurve(kYoungs, kDepth, 0.004, 0);
  IndentationFitOptions half_space;
  half_space.indenter = Indenter();
  const IndentationFit fit = FitIndentationCurve(layer.indentation, layer.force, half_space);
  EXPECT_GT(fit.youngs_modulus, 1.2 * kYoungs);
  EXPECT_GT(fit.relative_rms, 1e-3);  // and the shape does not fit
}

TEST(Calibration, CurvesThatCannotDetermineTheUnknownsSaySo) {
  IndentationFitOptions options;
  options.indenter = Indenter();
  options.fit_depth = true;
  // Three readings beyond contact for two unknowns and a noise estimate.
  const Curve short_curve = MakeCurve(kYoungs, kDepth, 0.006, 0);
  const std::vector<double> three_delta(short_curve.indentation.begin(),
                                        short_curve.indentation.begin() + 4);
  const std::vector<double> three_force(short_curve.force.begin(), short_curve.force.begin() + 4);
  IndentationFit fit = FitIndentationCurve(three_delta, three_force, options);
  EXPECT_FALSE(fit.converged);
  EXPECT_NE(fit.message.find("needs 4"), std::string::npos) << fit.message;
  // A half-space's curve: no depth explains it better than the largest allowed.
  const Curve deep = MakeCurve(kYoungs, kInfinity, 0.006, 0);
  fit = FitIndentationCurve(deep.indentation, deep.force, options);
  EXPECT_TRUE(fit.depth_at_bound);
  EXPECT_NE(fit.message.find("not determined"), std::string::npos) << fit.message;
  // E is still close: at the 0.2 m bound χ ≤ 0.04 leaves the law ~3.5 % above Hertz's.
  EXPECT_NEAR(fit.youngs_modulus, kYoungs, 0.05 * kYoungs);
  // A bound on the fitted depth shallower than the indentation.
  options.max_depth = 0.004;
  fit = FitIndentationCurve(short_curve.indentation, short_curve.force, options);
  EXPECT_FALSE(fit.converged);
  EXPECT_NE(fit.message.find("max_depth"), std::string::npos) << fit.message;
  options.max_depth = 0.2;
  // Pressed deeper than the layer it is said to have.
  options.fit_depth = false;
  options.depth = 0.003;
  fit = FitIndentationCurve(short_curve.indentation, short_curve.force, options);
  EXPECT_FALSE(fit.converged);
  EXPECT_NE(fit.message.find("deeper than the layer"), std::string::npos) << fit.message;
  // Only the approach, with the contact point fitted: no travel to fit.
  options.fit_contact_point = true;
  fit = FitIndentationCurve({-2e-4, -1e-4, 0.0, 0.0}, {0.0, 0.01, 0.02, 0.03}, options);
  EXPECT_FALSE(fit.converged);
  EXPECT_NE(fit.message.find("no reading beyond indentation 0"), std::string::npos) << fit.message;
  options.fit_contact_point = false;
  // No force at all.
  const std::vector<double> zeros(short_curve.indentation.size(), 0.0);
  options.depth = kDepth;
  fit = FitIndentationCurve(short_curve.indentation, zeros, options);
  EXPECT_FALSE(fit.converged);
  EXPECT_NE(fit.message.find("no positive force"), std::string::npos) << fit.message;
}

TEST(Calibration, AnOffLoggerZeroIsFoundWithTheContactPoint) {
  // The logger's zero 0.4 mm before first contact (readings of no force first) and 0.3 mm
  // after it (the first reading already pressed): F = law(δ − c).
  for (double offset : {4e-4, -3e-4}) {
    Curve curve;
    for (int i = 0; i <= 40; ++i) {
      const double logged = -5e-4 + 6.5e-3 * i / 40;
      curve.indentation.push_back(logged);
      const double travel = logged - offset;
      curve.force.push_back(
          travel > 0 ? LayeredIndentationForce(Indenter(), kYoungs, kDepth, travel).force : 0);
    }
    IndentationFitOptions options;
    options.indenter = Indenter();
    options.fit_depth = true;
    options.fit_contact_point = true;
    const IndentationFit fit = FitIndentationCurve(curve.indentation, curve.force, options);
    ASSERT_TRUE(fit.converged) << fit.message;
    EXPECT_EQ(fit.readings, 41);  // the approach counts: it says where contact is
    EXPECT_NEAR(fit.contact_offset, offset, 1e-8) << DescribeFit(fit);
    EXPECT_NEAR(fit.youngs_modulus, kYoungs, 1e-5 * kYoungs) << DescribeFit(fit);
    EXPECT_NEAR(fit.depth, kDepth, 1e-5 * kDepth) << DescribeFit(fit);
    // Taking the logger's zero as contact instead misfits the same curve visibly.
    options.fit_contact_point = false;
    const IndentationFit naive = FitIndentationCurve(curve.indentation, curve.force, options);
    EXPECT_GT(naive.relative_rms, 1e-3) << DescribeFit(naive);
    EXPECT_GT(std::abs(naive.youngs_modulus / kYoungs - 1), 0.02) << DescribeFit(naive);
  }
}

TEST(Calibration, IndentationResidualPassesTheGradientChecker) {
  // The residual is a polynomial in χ = √(Rδ)/h times δ^{3/2}: smooth in ln E and ln h,
  // and C¹ in the contact offset c (0.2 mm here), whose kink sits 0.1 mm or more from every
  // reading. Ceres's Ridders differences start at their relative step times the parameter,
  // or at the step itself for a parameter near zero — as c in metres is — so the default
  // start (1e-2) would step across the kink; a start of 1e-7 stays on one side (central
  // differences of this residual agree with the analytic values to 1e-9 there). The reading
  // before contact (δ = 0.1 mm) has r and ∂r all zero.
  for (bool half_space : {false, true}) {
    for (double indentation : {1e-4, 3e-4, 2e-3, 6e-3}) {
      std::unique_ptr<ceres::CostFunction> residual(
          NewIndentationResidual(Indenter(), indentation, 0.2, 0.5, half_space));
      ceres::NumericDiffOptions numeric;
      numeric.ridders_relative_initial_step_size = 1e-7;
      const std::vector<const ceres::Manifold*>* euclidean = nullptr;  // every block is R
      ceres::GradientChecker checker(residual.get(), euclidean, numeric);
      double log_youngs = std::log(3e4), log_depth = std::log(0.012), offset = 2e-4;
      const double* parameters[] = {&log_youngs, &log_depth, &offset};
      ceres::GradientChecker::ProbeResults results;
      EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results))
          << results.error_log << " (half space " << half_space << ", delta " << indentation << ")";
    }
  }
}

}  // namespace
}  // namespace ergo
