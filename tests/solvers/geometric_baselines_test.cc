// The geometric baselines (solvers/geometric_baselines.h): every residual's analytic
// Jacobian against ceres::GradientChecker, a rigid flat-bottomed body on a flat plate (the
// known answer: uniform pressure, and both baselines return the flat support), and a ball
// on the same plate (the support rises towards the ball but never through it).
#include <memory>
#include <random>

#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "problems/bump_scenario.h"
#include "solvers/geometric_baselines.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

void ExpectJacobianMatches(ceres::CostFunction* cost, std::vector<double>& values) {
  std::vector<double*> parameters;
  for (double& v : values) parameters.push_back(&v);
  ceres::NumericDiffOptions numeric;
  const std::vector<const ceres::Manifold*>* euclidean = nullptr;
  ceres::GradientChecker checker(cost, euclidean, numeric);
#if defined(__SANITIZE_ADDRESS__)
  // See tests/contact/penalty_cost_function_test.cc: no ProbeResults under ASan.
  EXPECT_TRUE(checker.Probe(parameters.data(), 1e-9, nullptr));
#else
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters.data(), 1e-9, &results)) << results.error_log;
#endif
}

TEST(SolversBaselines, GradientCheckerPassesOnEveryResidual) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  {
    TargetResidual target(0.7, 0.003);
    std::vector<double> d = {normal(rng) * 1e-3};
    ExpectJacobianMatches(&target, d);
  }
  for (int designed : {0, 1, 4}) {
    UmbrellaResidual umbrella(2.5, designed, 6);
    std::vector<double> d(static_cast<size_t>(designed) + 1);
    for (double& v : d) v = normal(rng) * 1e-3;
    ExpectJacobianMatches(&umbrella, d);
  }
  Eigen::MatrixXd B = Eigen::MatrixXd::Random(3, 7);
  Eigen::VectorXd b = Eigen::VectorXd::Random(3);
  BalanceResidual balance(B, b);
  std::vector<double> p(7);
  for (double& v : p) v = 1 + 0.1 * normal(rng);
  ExpectJacobianMatches(&balance, p);
}

// The bump scene's plate made flat, its top designed in the filtered space.
Scenario FlatPlate() {
  BumpScenarioOptions options;
  options.bump_height = 0;
  options.edge_length = 0.016;
  options.plate_cells = 12;
  Scenario scenario = MakeBumpScenario(options);
  scenario.design.parameterization = DesignParameterization::kFiltered;
  scenario.design.filter_radius = 0.02;
  return scenario;
}

TEST(SolversBaselines, AFlatBottomedBodyOnAFlatPlateGetsTheFlatPlate) {
  const Scenario plate = FlatPlate();
  const double top = plate.support.vertices.col(1).maxCoeff();
  LayeredBodyOptions body_options;
  body_options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  // A 6 cm cube resting 2 mm above the plate, well inside its designed top.
  const LayeredBody cube = testing::MakeHollowCubeBody(0.06, 6, 1e4, 0.45, body_options,
                                                       Eigen::Vector3d(0, top + 0.032, 0));
  const DesignProblem problem(cube, plate.support, RestState(cube), plate.design);
  const Eigen::VectorXd x0 = problem.InitialDesign();
  for (const bool sit_and_relax : {true, false}) {
    const BaselineDesign design = sit_and_relax ? SitAndRelaxDesign(problem, RestState(cube), {})
                                                : PoseToSeatDesign(problem, RestState(cube), {});
    SCOPED_TRACE(design.Describe());
    EXPECT_GT(design.weighted_vertices, 10);  // the 6 cm face over a 13 mm grid
    // Every target is "stay where you are": the fit moves nothing (Ceres' linear solve to
    // round-off on millimetre-scale numbers).
    EXPECT_LT(design.fit.displacement.cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((design.x - x0).cwiseAbs().maxCoeff(), 1e-10);
    if (!sit_and_relax) {
      // The balance holds: the bottom face carries the weight.
      EXPECT_LT(design.balance_residual, 1e-4);
      EXPECT_GT(design.contact_vertices, 10);
    }
  }
}

TEST(SolversBaselines, TheSupportRisesTowardsABallAsFarAsItsSmoothnessAllows) {
  const Scenario plate = FlatPlate();
  const DesignProblem problem = plate.MakeProblem();
  for (const bool sit_and_relax : {true, false}) {
    auto design_with = [&](double smoothness) {
      BaselineOptions options;
      options.negative_image_depth = 0.01;
      options.fit.smoothness = smoothness;
      return sit_and_relax ? SitAndRelaxDesign(problem, plate.start, options)
                           : PoseToSeatDesign(problem, plate.start, options);
    };
    const BaselineDesign design = design_with(1.0);
    SCOPED_TRACE(design.Describe());
    const Eigen::VectorXd& d = design.fit.displacement;
    // Raised under the ball: its lowest point touches at d = 0 and the support curves up
    // around it (a sphere's underside is millimetres above the plate within 1–2 cm).
    EXPECT_GT(d.maxCoeff(), 1e-3);
    EXPECT_LT(design.fit.rms_misfit, 0.5 * d.maxCoeff());
    // The smoothness term dips the support a little near the clamped rim, no more.
    EXPECT_GT(d.minCoeff(), -0.05 * d.maxCoeff());
    // Without smoothness the fit meets every target (the least squares is then separable);
    // more smoothness trades misfit for a flatter support.
    const BaselineDesign exact = design_with(1e-6);
    for (Eigen::Index v = 0; v < d.size(); ++v) {
      if (exact.fit.weight[v] > 0) {
        EXPECT_NEAR(exact.fit.displacement[v], exact.fit.target[v], 1e-6) << v;
      }
    }
    EXPECT_LT(design_with(0.1).fit.rms_misfit, design_with(10).fit.rms_misfit);
    // The design space reproduces the fitted positions (DesignFor is exact for the filter).
    const TriMesh designed = problem.SupportAt(design.x);
    EXPECT_LT((designed.vertices - design.fit.positions).cwiseAbs().maxCoeff(), 1e-9);
  }
}

}  // namespace
}  // namespace ergo
