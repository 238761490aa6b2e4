// Paper Fig. 5: for each exponent, ζ grows with the bump's spatial frequency.
#include "problems/bump_experiment.h"

#include <gtest/gtest.h>

namespace ergo {
namespace {

TEST(Problems, BumpCostGrowsMonotonicallyWithFrequencyForEveryExponent) {
  BumpScenarioOptions options;
  options.edge_length = 0.012;
  options.contact_stiffness = 1e7;  // κ, Pa/m
  const std::vector<BumpSweepPoint> points =
      RunBumpFrequencySweep(options, {0.03, 0.015, 0.01, 0.006});
  ASSERT_EQ(points.size(), 4u);
  for (const BumpSweepPoint& p : points) ASSERT_TRUE(p.converged) << p.message;
  for (int e = 0; e < 3; ++e) {
    EXPECT_DOUBLE_EQ(points.front().rescaled[e], 1.0);
    for (size_t i = 1; i < points.size(); ++i) {
      EXPECT_GT(points[i].zeta[e], points[i - 1].zeta[e])
          << "exponent " << e + 2 << " between widths " << points[i - 1].width << " and "
          << points[i].width;
    }
  }
  // Higher exponents penalise the spike more: the rescaled rise is ordered e=2 < e=3 < e=4.
  EXPECT_LT(points.back().rescaled[0], points.back().rescaled[1]);
  EXPECT_LT(points.back().rescaled[1], points.back().rescaled[2]);
}

}  // namespace
}  // namespace ergo
