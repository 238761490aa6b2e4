// The time split of a design evaluation (ergo/design/evaluation_timing.h) on the small bump
// scene: every part is non-negative, the parts add up to no more than the evaluation's wall
// time, and the counts are the equilibrium's own — for a cold evaluation (placed afresh) and
// for a warm one after a small step (tangent predictor); sums and the JSON form keep every
// entry.
#include "ergo/design/evaluation_timing.h"

#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/design/design_problem.h"
#include "problems/bump_scenario.h"

namespace ergo {
namespace {

// Disjoint intervals inside the total: their sum exceeds it only by rounding.
constexpr double kRounding = 1e-9;  // s

void ExpectConsistent(const DesignEvaluation& e, const std::string& what) {
  SCOPED_TRACE(what);
  const EvaluationTiming& t = e.timing;
  std::cout << what << ": " << t.BriefReport() << "\n";
  ForEachTimingEntry(
      t,
      [&](const char* name, double seconds) {
        if (std::string(name) == "other_s")
          EXPECT_GE(seconds, -kRounding) << name;
        else
          EXPECT_GE(seconds, 0.0) << name;
      },
      [&](const char* name, long count) { EXPECT_GE(count, 0) << name; });
  EXPECT_LE(t.PartsSeconds(), t.total_seconds + kRounding);
  EXPECT_GT(t.total_seconds, 0.0);
  // The equilibrium's parts and counts, gathered once.
  const EquilibriumResult& q = e.equilibrium;
  EXPECT_EQ(t.equilibria, 1);
  EXPECT_EQ(t.newton_iterations, q.iterations);
  EXPECT_EQ(t.factorizations, q.factorizations);
  EXPECT_EQ(t.pcg_iterations, q.pcg_iterations);
  EXPECT_EQ(t.line_search_trials, q.line_search_trials);
  EXPECT_EQ(t.assembly_seconds, q.assembly_seconds);
  EXPECT_EQ(t.contact_seconds, q.contact_seconds);
  EXPECT_EQ(t.factorization_seconds, q.factorization_seconds);
  EXPECT_EQ(t.solve_seconds, q.solve_seconds);
  EXPECT_EQ(t.line_search_seconds, q.line_search_seconds);
  EXPECT_LE(q.assembly_seconds + q.contact_seconds + q.factorization_seconds + q.solve_seconds +
                q.line_search_seconds,
            q.total_seconds + kRounding);
  EXPECT_LE(q.total_seconds, t.total_seconds);
  // Each Newton iteration assembles, detects contact and tries at least one step.
  EXPECT_GT(t.assembly_seconds, 0.0);
  EXPECT_GT(t.contact_seconds, 0.0);
  EXPECT_GE(t.line_search_trials, t.newton_iterations);
  EXPECT_GT(t.adjoint_seconds, 0.0);  // evaluated with the gradient
}

TEST(Design, EvaluationTimingPartsAreNonNegativeAddUpAndCountWhatTheEquilibriumDid) {
  BumpScenarioOptions options;
  options.edge_length = 0.015;  // a coarse ball: the test is about bookkeeping
  const Scenario scenario = MakeBumpScenario(options);
  DesignProblem problem = scenario.MakeProblem();
  problem.set_placement(DesignPlacement::kFollowed);
  const Eigen::VectorXd x0 = problem.InitialDesign();

  // Cold: the path's first evaluation places the body afresh and factorises.
  const DesignEvaluation cold = problem.Evaluate(x0, true);
  ASSERT_TRUE(cold.ok) << cold.message;
  ExpectConsistent(cold, "cold");
  EXPECT_EQ(cold.timing.fresh_placements, 1);
  EXPECT_GT(cold.timing.placement_seconds, 0.0);
  EXPECT_GE(cold.timing.factorizations, 1);
  EXPECT_GT(cold.timing.factorization_seconds, 0.0);

  // Warm, after a 0.1 mm step along −∇φ: no placement, the tangent predictor instead.
  const Eigen::VectorXd step =
      -cold.gradient * (1e-4 / problem.parameterization().VertexMoves(cold.gradient).maxCoeff());
  const DesignEvaluation warm = problem.Evaluate(x0 + step, true);
  ASSERT_TRUE(warm.ok) << warm.message;
  ExpectConsistent(warm, "warm");
  EXPECT_EQ(warm.timing.fresh_placements, 0);
  EXPECT_GT(warm.timing.predictor_seconds, 0.0);

  // Sums keep every entry; the JSON form reads back to the same split.
  EvaluationTiming both = cold.timing;
  both += warm.timing;
  EXPECT_EQ(both.equilibria, 2);
  EXPECT_EQ(both.newton_iterations, cold.timing.newton_iterations + warm.timing.newton_iterations);
  EXPECT_DOUBLE_EQ(both.total_seconds, cold.timing.total_seconds + warm.timing.total_seconds);
  EXPECT_NEAR(both.other_seconds(), cold.timing.other_seconds() + warm.timing.other_seconds(),
              kRounding);
  const EvaluationTiming read = TimingFromJson(TimingJson(both), "test");
  EXPECT_EQ(TimingJson(read), TimingJson(both));
  EXPECT_NE(both.BriefReport().find("Newton iterations"), std::string::npos);
}

}  // namespace
}  // namespace ergo
