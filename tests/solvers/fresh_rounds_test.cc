// Optimisation in fresh rounds (solvers/fresh_rounds.h) on a function whose path value
// drifts from its fresh value, as a followed equilibrium can: the driver keeps only what the
// fresh score confirms, never spends more than its budget (fresh checks included), restarts
// rounds from the kept design, and reports the optimiser's own value beside the fresh one.
#include "solvers/fresh_rounds.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include "solvers/analytic_objectives.h"

namespace ergo {
namespace {

// A stand-in for one design evaluation's time split (the quadratic costs nothing).
EvaluationTiming OneEquilibrium() {
  EvaluationTiming timing;
  timing.equilibria = 1;
  timing.factorizations = 2;
  timing.total_seconds = 1e-3;
  timing.assembly_seconds = 4e-4;
  return timing;
}

// A quadratic whose value along an optimiser's path is lowered by a "drift" that grows with
// the distance travelled since the path began (fresh score: the quadratic alone). The drift
// rewards long paths, as a warm-started equilibrium can reward a design only on its path.
class DriftingObjective : public Objective {
 public:
  DriftingObjective(std::shared_ptr<IllConditionedQuadratic> f, double drift)
      : f_(std::move(f)), drift_(drift) {}
  int NumParameters() const override { return f_->NumParameters(); }
  std::vector<std::string> TermNames() const override { return f_->TermNames(); }
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override {
    if (origin_.size() == 0) origin_ = x;
    ObjectiveValue v = f_->Evaluate(x, with_gradient);
    const double travelled = (x - origin_).norm();
    v.phi -= drift_ * travelled;
    v.terms = {{"f", 1, v.phi}};
    if (with_gradient && travelled > 0) v.gradient -= drift_ * (x - origin_) / travelled;
    v.timing = OneEquilibrium();
    return v;
  }
  std::unique_ptr<Objective> Clone() const override {
    return std::make_unique<DriftingObjective>(*this);
  }
  double LargestMove(const Eigen::VectorXd& dx) const override { return f_->LargestMove(dx); }
  double BoxHalfWidthForMove(double move) const override { return f_->BoxHalfWidthForMove(move); }
  double LengthScale() const override { return f_->LengthScale(); }
  std::string Describe() const override { return "drifting " + f_->Describe(); }

 private:
  std::shared_ptr<IllConditionedQuadratic> f_;
  double drift_;
  Eigen::VectorXd origin_;  // where this path began
};

TEST(Solvers, FreshRoundsKeepOnlyWhatTheFreshScoreConfirmsWithinTheBudget) {
  auto f = std::make_shared<IllConditionedQuadratic>(10, 100, 3);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(10);
  const double phi0 = f->Evaluate(x0, false).phi;
  long fresh_checks = 0;
  RoundsProblem problem;
  problem.make_objective = [&] { return std::make_unique<DriftingObjective>(f, 0.05 * phi0); };
  problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming* timing) {
    ++fresh_checks;
    *timing += OneEquilibrium();
    return f->Evaluate(x, false).phi;
  };
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer("ceres-lbfgs", {}, &error);
  ASSERT_TRUE(optimizer) << error;
  Budget budget;
  budget.max_evaluations = 60;
  RoundsOptions options;
  options.round_evaluations = 15;
  options.candidates = 3;
  const RoundsResult r = MinimizeInRounds(*optimizer, problem, x0, phi0, budget, {}, options);

  // The budget holds with the fresh checks counted.
  EXPECT_LE(r.result.evaluations, budget.max_evaluations);
  EXPECT_GE(r.rounds, 2);
  EXPECT_GE(fresh_checks, r.rounds);
  // What is kept is what the fresh score says, and it is better than the start.
  EXPECT_DOUBLE_EQ(r.kept_fresh_phi, f->Evaluate(r.kept_x, false).phi);
  EXPECT_DOUBLE_EQ(r.result.best_phi, r.kept_fresh_phi);
  EXPECT_LT(r.kept_fresh_phi, 0.5 * phi0);
  // The optimiser's own value there is flattered by its path's drift, and reported as such.
  EXPECT_LT(r.kept_followed_phi, r.kept_fresh_phi);
  EXPECT_DOUBLE_EQ(r.result.followed_phi, r.kept_followed_phi);
  // Each kept candidate was the best of its round's fresh checks.
  ASSERT_FALSE(r.candidate_fresh_phi.empty());
  ASSERT_GE(r.kept_candidate, 0);
  for (double value : r.candidate_fresh_phi)
    EXPECT_LE(r.candidate_fresh_phi[r.kept_candidate], value);
  // The history runs on across rounds, its time split too.
  for (size_t i = 1; i < r.result.history.size(); ++i) {
    EXPECT_GE(r.result.history[i].evaluations, r.result.history[i - 1].evaluations);
    EXPECT_GT(r.result.history[i].iteration, r.result.history[i - 1].iteration);
    EXPECT_GE(r.result.history[i].timing.equilibria, r.result.history[i - 1].timing.equilibria);
    EXPECT_GE(r.result.history[i].timing.total_seconds,
              r.result.history[i - 1].timing.total_seconds);
  }
  // The run's time split sums every evaluation counted, fresh checks included, once.
  EXPECT_EQ(r.result.timing.equilibria, r.result.evaluations);
  EXPECT_EQ(r.result.timing.factorizations, 2 * r.result.evaluations);
  EXPECT_NEAR(r.result.timing.total_seconds, 1e-3 * r.result.evaluations, 1e-12);
  EXPECT_NEAR(r.result.timing.other_seconds(), 6e-4 * r.result.evaluations, 1e-12);
  ASSERT_FALSE(r.result.history.empty());
  EXPECT_LE(r.result.history.back().timing.equilibria, r.result.timing.equilibria);
}

TEST(Solvers, FreshRoundsReturnTheStartWhenNothingBeatsItAfresh) {
  // Every move looks better on the path (the drift) but is worse afresh: f grows away from
  // x0 = its minimiser.
  auto f = std::make_shared<IllConditionedQuadratic>(4, 10, 5);
  const Eigen::VectorXd x0 = f->Minimizer();
  RoundsProblem problem;
  problem.make_objective = [&] { return std::make_unique<DriftingObjective>(f, 1.0); };
  problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming*) {
    return f->Evaluate(x, false).phi;
  };
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer("steepest", {}, &error);
  Budget budget;
  budget.max_evaluations = 30;
  RoundsOptions options;
  options.round_evaluations = 10;
  options.candidates = 2;
  const RoundsResult r = MinimizeInRounds(*optimizer, problem, x0, 0.0, budget, {}, options);
  EXPECT_EQ(r.kept_x, x0);
  EXPECT_EQ(r.kept_fresh_phi, 0.0);
  EXPECT_EQ(r.kept_candidate, -1);
  EXPECT_NE(r.result.stop_reason.find("placed afresh"), std::string::npos) << r.result.stop_reason;
}

// Records the budget each round is given and delegates to a real optimiser.
class BudgetRecorder : public Optimizer {
 public:
  explicit BudgetRecorder(std::unique_ptr<Optimizer> inner) : inner_(std::move(inner)) {}
  std::string name() const override { return inner_->name(); }
  OptimizerResult Minimize(Objective& objective, const Eigen::VectorXd& x0, const Budget& budget,
                           const RunControl& control) override {
    round_seconds.push_back(budget.max_seconds);
    return inner_->Minimize(objective, x0, budget, control);
  }
  std::vector<double> round_seconds;

 private:
  std::unique_ptr<Optimizer> inner_;
};

// Under a time budget a round leaves room for its fresh checks (the caller's estimate of one
// check first, the measured mean after), and a budget too small for a round and its checks
// ends the run before it starts, naming the whole budget.
TEST(Solvers, FreshRoundsKeepTheirChecksInsideATimeBudget) {
  auto f = std::make_shared<IllConditionedQuadratic>(6, 10, 7);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  const double phi0 = f->Evaluate(x0, false).phi;
  RoundsProblem problem;
  problem.make_objective = [&] { return std::make_unique<DriftingObjective>(f, 0.0); };
  problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming*) {
    return f->Evaluate(x, false).phi;
  };
  Budget budget;
  budget.max_evaluations = 40;
  budget.max_seconds = 100;
  RoundsOptions options;
  options.round_evaluations = 10;
  options.candidates = 3;
  options.fresh_score_seconds = 2;  // three checks: 6 s kept back from the first round
  BudgetRecorder optimizer(MakeOptimizer("nlopt-lbfgs", {}, nullptr));
  const RoundsResult r = MinimizeInRounds(optimizer, problem, x0, phi0, budget, {}, options);
  ASSERT_GE(optimizer.round_seconds.size(), 2u);
  // The analytic rounds take far less than 0.1 s; its checks measure about nothing.
  EXPECT_LE(optimizer.round_seconds[0], 94.0);
  EXPECT_GT(optimizer.round_seconds[0], 93.9);
  EXPECT_GT(optimizer.round_seconds[1], 99.9);
  EXPECT_LT(r.kept_fresh_phi, phi0);

  options.fresh_score_seconds = 30;  // a round and its three checks need 120 s of the 100
  BudgetRecorder idle(MakeOptimizer("nlopt-lbfgs", {}, nullptr));
  const RoundsResult none = MinimizeInRounds(idle, problem, x0, phi0, budget, {}, options);
  EXPECT_TRUE(idle.round_seconds.empty());
  EXPECT_EQ(none.kept_x, x0);
  EXPECT_EQ(none.result.stop_reason, "budget: 100 s wall");
}

// Past the time budget one design is still placed afresh so that the round is not lost; if
// the body finds no equilibrium on the round's best (a NaN score), the next is placed instead
// of giving the whole round up.
TEST(Solvers, FreshRoundsPastTheBudgetTryTheNextDesignWhenTheBestFindsNoEquilibrium) {
  auto f = std::make_shared<IllConditionedQuadratic>(6, 10, 7);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
  const double phi0 = f->Evaluate(x0, false).phi;
  int checks = 0;
  RoundsProblem problem;
  problem.make_objective = [&] { return std::make_unique<DriftingObjective>(f, 0.0); };
  problem.fresh_score = [&](const Eigen::VectorXd& x, EvaluationTiming*) {
    std::this_thread::sleep_for(std::chrono::milliseconds(60));  // past the 50 ms budget
    return checks++ == 0 ? std::numeric_limits<double>::quiet_NaN() : f->Evaluate(x, false).phi;
  };
  Budget budget;
  budget.max_evaluations = 40;
  budget.max_seconds = 0.05;
  RoundsOptions options;
  options.candidates = 3;
  BudgetRecorder optimizer(MakeOptimizer("nlopt-lbfgs", {}, nullptr));
  const RoundsResult r = MinimizeInRounds(optimizer, problem, x0, phi0, budget, {}, options);
  EXPECT_EQ(checks, 2) << "the best failed, the next was placed, and no third past the budget";
  EXPECT_LT(r.kept_fresh_phi, phi0);
  EXPECT_NE(r.kept_x, x0);
}

}  // namespace
}  // namespace ergo
