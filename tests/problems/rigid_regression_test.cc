// The rigid support is the fast path and stays what it was: the quick presets' initial
// evaluation (equilibrium afresh, φ, ζ's two halves, Newton iterations) pinned to the
// values measured before the soft-support seam went in (commit 42f3a73, this machine's
// Release build). A change that moves them on purpose must say so and re-pin them.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "ergo/design/design_problem.h"
#include "problems/chair_scenario.h"
#include "problems/mouse_scenario.h"
#include "problems/shoe_scenario.h"

namespace ergo {
namespace {

struct Pinned {
  double phi, zeta_human, zeta_support;
  int newton_iterations;
};

void Check(const std::string& name, const Scenario& scenario, const Pinned& pinned) {
  DesignProblem problem = scenario.MakeProblem();
  const DesignEvaluation e = problem.Evaluate(problem.InitialDesign(), false);
  ASSERT_TRUE(e.ok) << e.message;
  std::printf("[ pinned   ] %s: {%.17g, %.17g, %.17g, %d}\n", name.c_str(), e.phi, e.zeta_human,
              e.zeta_support, e.equilibrium.iterations);
  // Floating-point sums are in a fixed order (assembly by colour, contacts sorted): the same
  // build reproduces them bit for bit. 1e-9 relative leaves room for another compiler's
  // rounding and catches any change of the model, which moves ζ by far more.
  EXPECT_NEAR(e.phi, pinned.phi, 1e-9 * pinned.phi) << name;
  EXPECT_NEAR(e.zeta_human, pinned.zeta_human, 1e-9 * pinned.zeta_human) << name;
  EXPECT_NEAR(e.zeta_support, pinned.zeta_support, 1e-9 * pinned.zeta_support) << name;
  EXPECT_EQ(e.equilibrium.iterations, pinned.newton_iterations) << name;
}

TEST(RigidSupport, QuickPresetsInitialScoresAreThoseBeforeTheSoftSupportSeam) {
  Check("chair", MakeChairScenario(ChairScenarioOptions::FromPreset("quick")),
        {62678369840.868912, 27913651031.255821, 34764718809.613091, 13});
  // The shoe as it was pinned: its load through the core's centre (the default until
  // 2026-12-07, when quiet standing's load point became the default).
  ShoeScenarioOptions shoe = ShoeScenarioOptions::FromPreset("quick");
  shoe.load_point.reset();
  Check("shoe", MakeShoeScenario(shoe),
        {39302315561989.844, 12125294586303.48, 27177020975686.367, 14});
  Check("mouse", MakeMouseScenario(MouseScenarioOptions::FromPreset("quick")),
        {3765347443.7541151, 384636753.7489816, 3380710690.0051336, 8});
}

}  // namespace
}  // namespace ergo
