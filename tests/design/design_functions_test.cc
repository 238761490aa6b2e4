// The optimiser-facing adapters report exactly the problem's φ and ∇φ, scaled, and fail
// (rather than return a number) when the equilibrium fails; a Ceres L-BFGS and an NLopt MMA
// run through them lower φ on a small problem.
#include "ergo/design/design_functions.h"

#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <gtest/gtest.h>
#include <nlopt.hpp>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

// The soft cube resting flat on a slab with a 4 mm bump under one side.
struct BumpScene {
  LayeredBody body;
  TriMesh support;
};

BumpScene MakeBumpScene() {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  BumpScene scene{
      testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.056, 0)), {}};
  scene.support =
      MakeHeightfieldBlock({-0.1, -0.05, -0.1}, {0.1, 0, 0.1}, {10, 1, 10}, [](double x, double z) {
        return 0.004 * std::exp(-((x - 0.02) * (x - 0.02) + z * z) / (0.02 * 0.02));
      });
  return scene;
}

DesignOptions Options() {
  DesignOptions options;
  options.equilibrium.contact_stiffness = 5e6;  // κ, Pa/m
  options.parameterization = DesignParameterization::kNormalDisplacement;
  return options;
}

TEST(DesignFunctions, CeresAdapterReturnsTheScaledObjectiveAndGradient) {
  BumpScene scene = MakeBumpScene();
  DesignProblem problem(scene.body, scene.support, RestState(scene.body), Options());
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const DesignEvaluation direct = problem.Evaluate(x0, true);
  ASSERT_TRUE(direct.ok) << direct.message;
  DesignFirstOrderFunction function(&problem, x0, {direct.phi, 1e-3});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(x0.size()), gradient(x0.size());
  double cost = 0;
  ASSERT_TRUE(function.Evaluate(u.data(), &cost, gradient.data()));
  EXPECT_DOUBLE_EQ(cost, 1.0);
  EXPECT_LT((gradient - direct.gradient * (1e-3 / direct.phi)).norm(), 1e-12 * gradient.norm());
}

TEST(DesignFunctions, AdaptersReportAFailedEquilibriumAsAFailure) {
  BumpScene scene = MakeBumpScene();
  DesignOptions options = Options();
  options.equilibrium.max_iterations = 1;
  DesignProblem problem(scene.body, scene.support, TranslatedRestState(scene.body, {0, 0.05, 0}),
                        options);
  const Eigen::VectorXd x0 = problem.InitialDesign();
  DesignFirstOrderFunction function(&problem, x0, {1.0, 1.0});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(x0.size()), gradient(x0.size());
  double cost = 0;
  EXPECT_FALSE(function.Evaluate(u.data(), &cost, gradient.data()));
  NloptDesignData data{&problem, x0, {1.0, 1.0}, nullptr};
  EXPECT_EQ(
      NloptDesignObjective(static_cast<unsigned>(x0.size()), u.data(), gradient.data(), &data),
      std::numeric_limits<double>::infinity());
}

TEST(DesignFunctions, CeresLbfgsAndNloptMmaLowerTheObjectiveThroughTheAdapters) {
  BumpScene scene = MakeBumpScene();
  DesignProblem problem(scene.body, scene.support, RestState(scene.body), Options());
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const double phi0 = problem.Evaluate(x0, false).phi;
  {
    DesignProblem copy(problem);
    ceres::GradientProblem gradient_problem(new DesignFirstOrderFunction(&copy, x0, {phi0, 1e-3}));
    ceres::GradientProblemSolver::Options options;
    options.max_num_iterations = 8;
    ceres::GradientProblemSolver::Summary summary;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(x0.size());
    ceres::Solve(options, gradient_problem, u.data(), &summary);
    EXPECT_LT(summary.final_cost, 0.9) << summary.BriefReport();
  }
  {
    DesignProblem copy(problem);
    NloptDesignData data{&copy, x0, {phi0, 1e-3}, nullptr};
    nlopt::opt optimizer(nlopt::LD_MMA, static_cast<unsigned>(x0.size()));
    optimizer.set_min_objective(NloptDesignObjective, &data);
    optimizer.set_lower_bounds(-2.0);  // ±2 mm per vertex
    optimizer.set_upper_bounds(2.0);
    optimizer.set_maxeval(12);
    std::vector<double> u(x0.size(), 0.0);
    double best = 0;
    try {
      optimizer.optimize(u, best);
    } catch (const std::exception&) {
    }
    EXPECT_LT(optimizer.last_optimum_value(), 0.9);
  }
}

}  // namespace
}  // namespace ergo
