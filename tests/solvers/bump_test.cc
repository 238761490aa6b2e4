// The optimisers on a small ergonomic problem — the soft ball on a bumpy plate
// (problems/bump_scenario.h, the scenario's defaults): each lowers φ by at least 30 % within
// 60 evaluations, reports only φ values that an evaluation actually returned, counts every
// evaluation, and stops for the reason it gives. Also: the paper's eight probe lengths
// are exact, and an interruption returns the best design so far.
#include <algorithm>
#include <atomic>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "problems/bump_scenario.h"
#include "solvers/design_objective.h"
#include "solvers/optimizer.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// The scene is built once per process (meshing the ball takes a few seconds).
const Scenario& Bump() {
  static const Scenario scenario = MakeBumpScenario();
  return scenario;
}

// The problem as an optimiser's own path evaluates it (warm starts along the path, as the
// tools' rounds do; a fresh placement per evaluation costs 5× the Newton iterations).
DesignProblem FollowedProblem() {
  DesignProblem problem = Bump().MakeProblem();
  problem.set_placement(DesignPlacement::kFollowed);
  return problem;
}

// Every evaluation an optimiser made, as the objective returned it.
struct EvaluationLog {
  std::mutex mutex;
  std::vector<Eigen::VectorXd> x;
  std::vector<ObjectiveValue> value;

  RunControl Control() {
    RunControl control;
    control.on_evaluation = [this](const Eigen::VectorXd& design, const ObjectiveValue& v) {
      std::lock_guard<std::mutex> lock(mutex);
      x.push_back(design);
      value.push_back(v);
    };
    return control;
  }
  std::multiset<double> SuccessfulPhis() const {
    std::multiset<double> phis;
    for (const ObjectiveValue& v : value)
      if (v.ok) phis.insert(v.phi);
    return phis;
  }
};

class BumpOptimizerTest : public ::testing::TestWithParam<std::string> {};

TEST_P(BumpOptimizerTest, LowersPhiByAThirdWithin60EvaluationsAndReportsOnlyEvaluatedValues) {
  // 60 evaluations; 20 under the sanitizers (10-20x slower; measured in the Release run at 20,
  // every optimiser is 58.6 % (steepest) to 92.3 % lower: the 30 % asserted holds with room).
  constexpr int kBudget = testing::SanitizedBuild() ? 20 : 60;
  if (testing::SanitizedBuild() &&
      (GetParam() == "nlopt-mma" || GetParam() == "nlopt-ccsaq" || GetParam() == "nlopt-tnewton"))
    GTEST_SKIP() << "nlopt-lbfgs runs the same NLopt adapter under the sanitizers";
  DesignObjective objective(FollowedProblem());
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer(GetParam(), {}, &error);
  ASSERT_TRUE(optimizer) << error;
  Budget budget;
  budget.max_evaluations = kBudget;
  EvaluationLog log;
  const OptimizerResult result =
      optimizer->Minimize(objective, objective.problem().InitialDesign(), budget, log.Control());
  std::cout << result.FullReport();
  ASSERT_TRUE(result.ok) << result.stop_reason;

  EXPECT_GE(result.ReductionPercent(), 30.0);
  // Every evaluation is counted, by the run, by the observer and by the problem itself.
  EXPECT_LE(result.evaluations, kBudget);
  EXPECT_EQ(result.evaluations, static_cast<long>(log.value.size()));
  EXPECT_EQ(result.evaluations, objective.problem().counters().evaluations.load());
  long newton = 0, failed = 0;
  for (const ObjectiveValue& v : log.value) {
    newton += v.newton_iterations;
    failed += v.ok ? 0 : 1;
  }
  EXPECT_EQ(result.newton_iterations, newton);
  EXPECT_EQ(result.failed_evaluations, failed);
  // The time split covers the same evaluations: one equilibrium each.
  EXPECT_EQ(result.timing.equilibria, result.evaluations);
  EXPECT_EQ(result.timing.newton_iterations, newton);

  // Every φ reported was returned by a successful evaluation; the best is the lowest of them
  // and belongs to exactly the design returned.
  const std::multiset<double> phis = log.SuccessfulPhis();
  ASSERT_FALSE(phis.empty());
  EXPECT_EQ(result.best_phi, *phis.begin());
  bool best_found = false;
  for (size_t i = 0; i < log.x.size(); ++i) {
    best_found |= log.value[i].ok && log.value[i].phi == result.best_phi &&
                  log.x[i].size() == result.best_x.size() &&
                  (log.x[i].array() == result.best_x.array()).all();
  }
  EXPECT_TRUE(best_found) << "the reported best design was never evaluated with that φ";
  ASSERT_FALSE(result.history.empty());
  EXPECT_EQ(result.initial_phi, result.history.front().phi);
  long previous_evaluations = 0;
  EvaluationTiming previous_timing;
  for (const IterationRecord& record : result.history) {
    // Cumulative, like the evaluations.
    EXPECT_GE(record.timing.total_seconds, previous_timing.total_seconds);
    EXPECT_GE(record.timing.equilibria, previous_timing.equilibria);
    EXPECT_LE(record.timing.equilibria, result.timing.equilibria);
    previous_timing = record.timing;
    EXPECT_GT(phis.count(record.phi), 0u)
        << "iteration " << record.iteration << " reports φ = " << record.phi
        << ", which no evaluation returned";
    EXPECT_GE(record.evaluations, previous_evaluations);
    EXPECT_LE(record.evaluations, result.evaluations);
    previous_evaluations = record.evaluations;
  }

  // The stop reason says what happened: the budget exactly when it was used up.
  const bool budget_reason = result.stop_reason.rfind("budget:", 0) == 0;
  EXPECT_EQ(budget_reason, result.evaluations == kBudget) << result.stop_reason;
  if (budget_reason) {
    EXPECT_EQ(result.stop_reason, "budget: " + std::to_string(kBudget) + " evaluations");
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, BumpOptimizerTest, ::testing::ValuesIn(OptimizerNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// Sorted largest vertex moves of the probes from `from` among evaluations [begin, end).
std::vector<double> ProbeMoves(const DesignObjective& objective, const EvaluationLog& log,
                               const Eigen::VectorXd& from, size_t begin, size_t end) {
  std::vector<double> moves;
  for (size_t i = begin; i < end; ++i)
    moves.push_back(objective.problem().parameterization().VertexMoves(log.x[i] - from).maxCoeff());
  std::sort(moves.begin(), moves.end());
  return moves;
}

TEST(Solvers, PaperNcgTrialStepsMoveTheLargestVertexByExactlyThePapersLengths) {
  DesignObjective objective(FollowedProblem());
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer("paper-ncg", {}, nullptr);
  Budget budget;
  budget.max_evaluations = 17;  // x₀ and two rounds of eight probes
  EvaluationLog log;
  const Eigen::VectorXd x0 = objective.problem().InitialDesign();
  const OptimizerResult result = optimizer->Minimize(objective, x0, budget, log.Control());
  ASSERT_TRUE(result.ok) << result.stop_reason;
  ASSERT_EQ(log.x.size(), 17u);
  ASSERT_TRUE((log.x[0].array() == x0.array()).all());  // x₀ first, then the probes

  const std::vector<double> paper = {1e-6, 1e-5, 1e-4, 2e-4, 5e-4, 7e-4, 1e-3, 2e-3};
  // Iteration 1 probes from x₀; iteration 2 from the best of them.
  const std::vector<double> first = ProbeMoves(objective, log, x0, 1, 9);
  size_t accepted = 1;
  for (size_t i = 1; i < 9; ++i)
    if (log.value[i].ok && log.value[i].phi < log.value[accepted].phi) accepted = i;
  ASSERT_LT(log.value[accepted].phi, log.value[0].phi);
  const std::vector<double> second = ProbeMoves(objective, log, log.x[accepted], 9, 17);
  for (size_t j = 0; j < paper.size(); ++j) {
    EXPECT_NEAR(first[j], paper[j], 1e-12 * paper[j]) << "probe " << j << " of iteration 1";
    EXPECT_NEAR(second[j], paper[j], 1e-12 * paper[j]) << "probe " << j << " of iteration 2";
  }
}

TEST(Solvers, InterruptionFromAnotherThreadReturnsTheBestDesignSoFar) {
  DesignObjective objective(FollowedProblem());
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer("paper-ncg", {}, nullptr);
  Budget budget;
  budget.max_evaluations = 200;
  std::atomic<bool> stop{false};
  EvaluationLog log;
  RunControl control = log.Control();
  control.stop = &stop;
  auto observe = control.on_evaluation;
  // Probe threads raise the flag in the middle of the second round of probes, as a SIGINT
  // handler would.
  control.on_evaluation = [&](const Eigen::VectorXd& x, const ObjectiveValue& v) {
    observe(x, v);
    if (log.x.size() >= 12) stop = true;
  };
  const OptimizerResult result =
      optimizer->Minimize(objective, objective.problem().InitialDesign(), budget, control);
  EXPECT_EQ(result.stop_reason, "interrupted");
  ASSERT_TRUE(result.ok);
  EXPECT_LT(result.evaluations, 18);  // nothing started after the flag except what was running
  EXPECT_EQ(result.best_phi, *log.SuccessfulPhis().begin());
  EXPECT_LT(result.best_phi, result.initial_phi);
}

}  // namespace
}  // namespace ergo
