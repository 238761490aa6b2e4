// The adjoint gradient on the second scene of the issue: a soft ball (a layer meshed by the
// body builder) resting on a plate with a Gaussian bump, core translating vertically only,
// for the four design parameterisations (the filtered and spline ones check their pull-backs
// inside the whole adjoint chain). The pit scene (design_gradient_test.cc) covers free
// core rotation and every Voronoi region type; here the support is smooth and fine and the
// skin is a Mesh_3 surface.
#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "ergo/design/design_problem.h"
#include "problems/bump_scenario.h"
#include "tests/support/finite_difference.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

class DesignGradientBallOnBump : public ::testing::TestWithParam<DesignParameterization> {};

TEST_P(DesignGradientBallOnBump, AdjointGradientMatchesFiniteDifferences) {
  BumpScenarioOptions options;
  options.edge_length = 0.012;
  options.contact_stiffness = 1e7;  // κ, Pa/m
  Scenario scenario = MakeBumpScenario(options);
  scenario.design.parameterization = GetParam();
  // m, about two skin edges: the filter's radius, the spline's knot spacing
  scenario.design.filter_radius = 0.025;
  scenario.design.equilibrium.relative_tolerance = 1e-11;
  // Design only the plate's top vertices within 3 cm of the bump (keeps the component-wise
  // check affordable).
  for (Eigen::Index v = 0; v < scenario.support.vertices.rows(); ++v) {
    const Eigen::Vector3d p = scenario.support.vertices.row(v);
    scenario.design.active[v] =
        scenario.design.active[v] &&
        std::hypot(p.x() - options.bump_centre.x(), p.z() - options.bump_centre.y()) < 0.03;
  }
  DesignProblem problem = scenario.MakeProblem();
  const Eigen::VectorXd x0 = problem.InitialDesign();
  DesignEvaluation at = problem.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  problem.set_gamma(at.zeta / at.psi);
  at = problem.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  ASSERT_GT(at.zeta_support, 0);

  const Eigen::VectorXd& g = at.gradient;
  const Eigen::Index n = x0.size();
  std::mt19937 rng(29);
  std::normal_distribution<double> normal;
  std::vector<std::pair<std::string, Eigen::VectorXd>> directions = {
      {"along the gradient", g.normalized()}};
  // Under the sanitizers (10-20x slower) one random direction, two components and two
  // steps: the same code paths; the Release run checks the full set.
  const bool sanitized = testing::SanitizedBuild();
  for (int k = 0; k < (sanitized ? 1 : 3); ++k) {
    Eigen::VectorXd d(n);
    for (Eigen::Index i = 0; i < n; ++i) d[i] = normal(rng);
    directions.emplace_back("random " + std::to_string(k), d.normalized());
  }
  if (GetParam() == DesignParameterization::kNormalDisplacement) {
    // Component-wise: the four largest |∂φ/∂xᵢ| and eight more spread over the patch
    // (enough to catch a per-vertex mix-up at a third of the cost of all; under the
    // sanitizers one and one).
    for (Eigen::Index i : testing::CheckedComponents(g, sanitized ? 1 : 4, sanitized ? 1 : 8))
      directions.emplace_back("component " + std::to_string(i), Eigen::VectorXd::Unit(n, i));
  }
  double worst = 0;
  for (const auto& [name, d] : directions) {
    const double analytic = g.dot(d);
    double best = INFINITY;
    std::string report;
    const std::vector<double> steps =
        sanitized ? std::vector<double>{1e-6, 1e-7} : std::vector<double>{1e-6, 1e-7, 3e-8};
    for (double h : steps) {
      const DesignEvaluation plus = problem.Evaluate(x0 + h * d, false),
                             minus = problem.Evaluate(x0 - h * d, false);
      if (!plus.ok || !minus.ok) continue;
      const double fd = (plus.phi - minus.phi) / (2 * h);
      const double error = std::abs(fd - analytic) / std::max(std::abs(analytic), 1e-3 * g.norm());
      report += "  h=" + std::to_string(h) + " fd=" + std::to_string(fd) +
                " analytic=" + std::to_string(analytic) + "\n";
      best = std::min(best, error);
    }
    // The bound; see design_gradient_test.cc for the floor.
    EXPECT_LT(best, 1e-4) << name << "\n" << report;
    worst = std::max(worst, best);
  }
  std::cout << "ball on bump: worst relative error " << worst << " over " << directions.size()
            << " directions, " << n << " design variables\n";
}

INSTANTIATE_TEST_SUITE_P(Parameterizations, DesignGradientBallOnBump,
                         ::testing::Values(DesignParameterization::kPositions,
                                           DesignParameterization::kNormalDisplacement,
                                           DesignParameterization::kFiltered,
                                           DesignParameterization::kSpline),
                         [](const auto& info) {
                           switch (info.param) {
                             case DesignParameterization::kPositions:
                               return std::string("positions");
                             case DesignParameterization::kNormalDisplacement:
                               return std::string("normal");
                             case DesignParameterization::kFiltered:
                               return std::string("filtered");
                             case DesignParameterization::kSpline:
                               return std::string("spline");
                           }
                           return std::string("unknown");
                         });

}  // namespace
}  // namespace ergo
