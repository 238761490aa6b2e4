// The sliding-anchor spring as a Ceres cost function: GradientChecker in every region,
// consistency with the energy (‖r‖² = E, 2Jᵀr = ∇E), and a ceres::Problem whose minimiser
// is known in closed form.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <ceres/normal_prior.h>
#include <gtest/gtest.h>

#include "ergo/contact/penalty_cost_function.h"
#include "ergo/contact/point_feature_energy.h"
#include "tests/contact/contact_test_util.h"

namespace ergo {
namespace {

using contact_testing::AllRegions;
using contact_testing::Region;
using contact_testing::RegionName;
using contact_testing::Triangle;
using Eigen::Vector3d;

FeaturePositions RegionPositions(const Region& region, const Triangle& t) {
  std::array<int, 3> blocks;
  const int n = contact_testing::RegionVertexBlocks(region, &blocks);
  FeaturePositions x;
  for (int i = 0; i < n; ++i) x[i] = t[blocks[i] - 1];
  return x;
}

TEST(Contact, GradientCheckerPassesOnTheCostFunctionInEveryRegion) {
  std::mt19937 rng(5);
  const std::vector<const ceres::Manifold*>* euclidean = nullptr;  // all blocks are R³
  for (const Region& region : AllRegions()) {
    for (double scale : {1e-3, 0.1, 10.0}) {
      // GradientChecker differentiates with Ridders' method, whose first step is
      // max(ridders_relative_initial_step_size · |x|, that same number in metres): the
      // default 1e-2 m is ten times a millimetre triangle and crosses its degenerate
      // configurations. Start at 1e-4 of the geometry's scale instead.
      ceres::NumericDiffOptions numeric;
      numeric.ridders_relative_initial_step_size = 1e-4 * scale;
      for (int trial = 0; trial < 3; ++trial) {
        const Triangle t = contact_testing::RandomTriangle(rng, scale);
        Vector3d p = contact_testing::PointInRegion(rng, t, region, scale);
        FeaturePositions x = RegionPositions(region, t);
        const double k = std::pow(10.0, std::uniform_real_distribution<double>(2, 6)(rng));
        const std::unique_ptr<ceres::CostFunction> cost =
            MakeSlidingAnchorCostFunction(region.type, k);
        const int n = FeatureVertexCount(region.type);
        ASSERT_EQ(cost->parameter_block_sizes().size(), static_cast<std::size_t>(n + 1));
        ASSERT_EQ(cost->num_residuals(), 3);
        std::vector<double*> parameters = {p.data()};
        for (int i = 0; i < n; ++i) parameters.push_back(x[i].data());

        ceres::GradientChecker checker(cost.get(), euclidean, numeric);
#if defined(__SANITIZE_ADDRESS__)
        // Under AddressSanitizer Eigen stops trusting malloc's alignment and frees with its
        // own scheme, so ProbeResults, filled inside the (uninstrumented) Ceres library,
        // cannot be destroyed here. Probe without it; the Release build prints the log.
        EXPECT_TRUE(checker.Probe(parameters.data(), 1e-7, nullptr))
            << RegionName(region) << " scale " << scale;
#else
        ceres::GradientChecker::ProbeResults results;
        EXPECT_TRUE(checker.Probe(parameters.data(), 1e-7, &results))
            << RegionName(region) << " scale " << scale << "\n"
            << results.error_log;
#endif
      }
    }
  }
}

TEST(Contact, CostFunctionResidualIsConsistentWithTheEnergy) {
  std::mt19937 rng(17);
  for (const Region& region : AllRegions()) {
    for (double scale : {1e-3, 1.0, 10.0}) {
      const Triangle t = contact_testing::RandomTriangle(rng, scale);
      const Vector3d p = contact_testing::PointInRegion(rng, t, region, scale);
      const FeaturePositions x = RegionPositions(region, t);
      const double k = 2.5e4;
      Vector3d r;
      Eigen::Matrix<double, 3, 12> jacobian;
      ASSERT_TRUE(SlidingAnchorResidual(region.type, p, x, k, &r, &jacobian));
      const SlidingAnchorEnergy e = EvaluateSlidingAnchor(region.type, p, x, k, false);
      // r = √k (p − π): ‖r‖² = E and ∇E = 2 Jᵀ r.
      EXPECT_NEAR(r.squaredNorm(), e.energy, 1e-12 * e.energy) << RegionName(region);
      EXPECT_LT((r - std::sqrt(k) * (p - SlidingAnchor(region.type, p, x))).norm(),
                1e-12 * r.norm());
      const int size = e.size;
      EXPECT_LT((2 * jacobian.leftCols(size).transpose() * r - e.gradient.head(size)).norm(),
                1e-10 * e.gradient.norm())
          << RegionName(region);
      EXPECT_EQ(jacobian.rightCols(12 - size).norm(), 0.0);

      // Evaluate through the Ceres interface gives the same numbers, Jacobians row-major.
      const std::unique_ptr<ceres::CostFunction> cost =
          MakeSlidingAnchorCostFunction(region.type, k);
      const int n = FeatureVertexCount(region.type);
      std::vector<const double*> parameters = {p.data()};
      for (int i = 0; i < n; ++i) parameters.push_back(x[i].data());
      double residual[3];
      std::vector<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> blocks(n + 1);
      std::vector<double*> jacobians;
      for (auto& block : blocks) jacobians.push_back(block.data());
      ASSERT_TRUE(cost->Evaluate(parameters.data(), residual, jacobians.data()));
      EXPECT_EQ(Eigen::Map<Vector3d>(residual), r);
      for (int b = 0; b <= n; ++b) {
        EXPECT_EQ(Eigen::Matrix3d(blocks[b]), (jacobian.block<3, 3>(0, 3 * b)));
      }
      // Null Jacobian blocks (constant parameters) are allowed.
      jacobians[0] = nullptr;
      EXPECT_TRUE(cost->Evaluate(parameters.data(), residual, jacobians.data()));
      EXPECT_TRUE(cost->Evaluate(parameters.data(), residual, nullptr));
    }
  }
}

TEST(Contact, CostFunctionRefusesDegenerateFeatures) {
  const Vector3d p(0.1, 0.2, 0.3), a(1, 0, 0);
  double residual[3];
  const std::unique_ptr<ceres::CostFunction> edge =
      MakeSlidingAnchorCostFunction(FeatureType::kEdge, 1);
  const double* edge_parameters[] = {p.data(), a.data(), a.data()};
  EXPECT_FALSE(edge->Evaluate(edge_parameters, residual, nullptr));
  const Vector3d b(2, 0, 0), c(3, 0, 0);  // collinear: zero area
  const std::unique_ptr<ceres::CostFunction> face =
      MakeSlidingAnchorCostFunction(FeatureType::kFace, 1);
  const double* face_parameters[] = {p.data(), a.data(), b.data(), c.data()};
  EXPECT_FALSE(face->Evaluate(face_parameters, residual, nullptr));
}

TEST(Contact, CostFunctionSolvesASpringAgainstALoadInACeresProblem) {
  // Minimise k‖p − π(p)‖² + w‖p − q‖² with the support fixed: within q's region the answer
  // is p* = q − k/(k + w) · (q − π(q)) (the spring and the load share the normal direction).
  std::mt19937 rng(23);
  for (const Region& region : AllRegions()) {
    const double scale = 0.05;
    const Triangle t = contact_testing::RandomTriangle(rng, scale);
    const Vector3d q = contact_testing::PointInRegion(rng, t, region, scale);
    FeaturePositions x = RegionPositions(region, t);
    const double k = 4e4, w = 1e4;

    Vector3d p = q;
    ceres::Problem problem;
    std::vector<double*> blocks = {p.data()};
    for (int i = 0; i < FeatureVertexCount(region.type); ++i) blocks.push_back(x[i].data());
    problem.AddResidualBlock(MakeSlidingAnchorCostFunction(region.type, k).release(), nullptr,
                             blocks);
    for (std::size_t i = 1; i < blocks.size(); ++i) problem.SetParameterBlockConstant(blocks[i]);
    // The load: r = √w (p − q), a Ceres-provided cost.
    problem.AddResidualBlock(new ceres::NormalPrior(std::sqrt(w) * Eigen::Matrix3d::Identity(), q),
                             nullptr, p.data());
    ceres::Solver::Options options;
    options.function_tolerance = 1e-16;
    options.gradient_tolerance = 1e-16;
    options.parameter_tolerance = 1e-16;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
    const Vector3d expected = q - k / (k + w) * (q - SlidingAnchor(region.type, q, x));
    // Ceres stops on a relative cost change, which leaves ~√ε relative error in p.
    EXPECT_LT((p - expected).norm(), 1e-8 * scale) << RegionName(region) << "\n"
                                                   << summary.BriefReport();
  }
}

}  // namespace
}  // namespace ergo
