// One support for several bodies (solvers/population_objective.h): the aggregates' values
// on hand-computed cases and their partials against central differences; then a 3-body
// population of soft balls on the bump plate (different sizes and stiffnesses), whose
// value is each aggregate of the bodies' own normalised scores and whose gradient agrees
// with central differences of that composition, along itself and a random direction.
#include "solvers/population_objective.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <iostream>
#include <mutex>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "problems/bump_scenario.h"
#include "solvers/analytic_objectives.h"
#include "solvers/design_objective.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

PopulationOptions Options(PopulationAggregate aggregate) {
  PopulationOptions options;
  options.aggregate = aggregate;
  return options;
}

TEST(SolversPopulation, AggregatesHaveTheirHandComputedValuesAndPartials) {
  const std::vector<double> w = {0.5, 0.25, 0.25};
  const std::vector<double> r = {0.8, 1.2, 0.6};
  // mean: 0.4 + 0.3 + 0.15.
  EXPECT_NEAR(PopulationScore(r, w, Options(PopulationAggregate::kMean), nullptr), 0.85, 1e-15);
  // meanstd: σ² = 0.5·0.05² + 0.25·0.35² + 0.25·0.25² = 0.0475 (+ ε² = 1e-6).
  PopulationOptions meanstd = Options(PopulationAggregate::kMeanStd);
  meanstd.std_weight = 2;
  EXPECT_NEAR(PopulationScore(r, w, meanstd, nullptr), 0.85 + 2 * std::sqrt(0.0475 + 1e-6), 1e-14);
  // Every body alike (the start): σ_ε = ε, smooth.
  EXPECT_NEAR(PopulationScore({1, 1, 1}, w, meanstd, nullptr), 1 + 2e-3, 1e-15);
  // worst: within T·log(1/w_max) of the largest score, and equal to it as T → 0.
  PopulationOptions worst = Options(PopulationAggregate::kWorst);
  const double soft = PopulationScore(r, w, worst, nullptr);
  EXPECT_LE(soft, 1.2 + 1e-12);
  EXPECT_GE(soft, 1.2 + worst.temperature * std::log(0.25) - 1e-12);
  worst.temperature = 1e-4;
  EXPECT_NEAR(PopulationScore(r, w, worst, nullptr), 1.2 + 1e-4 * std::log(0.25), 1e-12);
  worst.temperature = 1e-3;
  // A score far above the rest does not overflow (the log-sum-exp is shifted by the maximum).
  EXPECT_NEAR(PopulationScore({1, 500, 2}, w, worst, nullptr), 500 + 1e-3 * std::log(0.25), 1e-9);

  // cvar, α = 0.5: the worst half by weight is 1.2 (w 0.25) and half of 0.8 (0.25 of 0.5).
  PopulationOptions cvar = Options(PopulationAggregate::kCvar);
  EXPECT_NEAR(PopulationScore(r, w, cvar, nullptr), (0.25 * 1.2 + 0.25 * 0.8) / 0.5, 1e-15);
  std::vector<double> cvar_partials;
  PopulationScore(r, w, cvar, &cvar_partials);
  EXPECT_EQ(cvar_partials, (std::vector<double>{0.5, 0.5, 0.0}));
  cvar.cvar_alpha = 0;  // the whole population: the mean
  EXPECT_NEAR(PopulationScore(r, w, cvar, nullptr), 0.85, 1e-15);
  cvar.cvar_alpha = 0.9;  // the worst 10 %: inside the worst body's weight
  EXPECT_NEAR(PopulationScore(r, w, cvar, nullptr), 1.2, 1e-15);
  cvar.cvar_alpha = 0.5;

  for (PopulationOptions options :
       {Options(PopulationAggregate::kMean), meanstd, Options(PopulationAggregate::kWorst), cvar}) {
    std::vector<double> partials;
    PopulationScore(r, w, options, &partials);
    for (size_t b = 0; b < r.size(); ++b) {
      std::vector<double> plus = r, minus = r;
      const double h = 1e-6;
      plus[b] += h;
      minus[b] -= h;
      const double fd = (PopulationScore(plus, w, options, nullptr) -
                         PopulationScore(minus, w, options, nullptr)) /
                        (2 * h);
      // Central differences of smooth functions of O(1) values: error O(h²) + 1e-16/h.
      EXPECT_NEAR(partials[b], fd, 1e-8) << PopulationAggregateName(options.aggregate) << " " << b;
    }
  }
  PopulationAggregate parsed;
  EXPECT_TRUE(ParsePopulationAggregate("worst", &parsed));
  EXPECT_EQ(parsed, PopulationAggregate::kWorst);
  EXPECT_TRUE(ParsePopulationAggregate("cvar", &parsed));
  EXPECT_EQ(parsed, PopulationAggregate::kCvar);
  EXPECT_FALSE(ParsePopulationAggregate("median", &parsed));
}

struct Ball {
  const char* name;
  double radius, youngs_modulus, weight;
};

TEST(SolversPopulation, ThreeBodiesShareOneDesignAndTheGradientMatchesDifferences) {
  // Three soft balls on one bump plate: one support mesh and one design space for all.
  std::vector<Scenario> scenes;
  for (const Ball& ball : {Ball{"small soft", 0.045, 0.8e4, 1}, Ball{"medium", 0.05, 1e4, 2},
                           Ball{"large stiff", 0.055, 1.3e4, 1}}) {
    BumpScenarioOptions options;
    options.edge_length = 0.016;
    options.ball_radius = ball.radius;
    options.youngs_modulus = ball.youngs_modulus;
    Scenario scene = MakeBumpScenario(options);
    scene.name = ball.name;
    scene.design.equilibrium.relative_tolerance = 1e-11;
    scene.design.placement = DesignPlacement::kFresh;  // deterministic per design
    scene.design.filter_radius = 0.025;                // the same filter for every body
    scenes.push_back(std::move(scene));
  }
  for (const Scenario& scene : scenes) {
    ASSERT_EQ(scene.support.vertices, scenes.front().support.vertices);
    ASSERT_EQ(scene.support.triangles, scenes.front().support.triangles);
  }
  std::vector<DesignProblem> problems;
  for (const Scenario& scene : scenes) problems.push_back(scene.MakeProblem());
  const Eigen::VectorXd x0 = problems.front().InitialDesign();
  std::vector<double> scales;
  for (DesignProblem& problem : problems) {
    const DesignEvaluation e = DesignProblem(problem).Evaluate(x0, false);
    ASSERT_TRUE(e.ok) << e.message;
    scales.push_back(e.phi);
  }
  const std::vector<double> weights = {0.25, 0.5, 0.25};
  auto population = [&](PopulationAggregate aggregate) {
    std::vector<PopulationMember> members;
    for (size_t b = 0; b < problems.size(); ++b)
      members.push_back({scenes[b].name, 4 * weights[b], scales[b],
                         std::make_unique<DesignObjective>(problems[b])});
    return PopulationObjective(std::move(members), Options(aggregate));
  };
  // F as a composition: each body's own φ, normalised and aggregated.
  auto composed = [&](const Eigen::VectorXd& x, const PopulationOptions& options) {
    std::vector<double> r;
    for (size_t b = 0; b < problems.size(); ++b) {
      const DesignEvaluation e = DesignProblem(problems[b]).Evaluate(x, false);
      EXPECT_TRUE(e.ok) << e.message;
      r.push_back(e.phi / scales[b]);
    }
    return PopulationScore(r, weights, options, nullptr);
  };

  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  Eigen::VectorXd random(x0.size());
  for (Eigen::Index i = 0; i < random.size(); ++i) random[i] = normal(rng);
  random.normalize();
  const std::vector<PopulationAggregate> aggregates =
      testing::SanitizedBuild() ? std::vector<PopulationAggregate>{PopulationAggregate::kMeanStd}
                                : std::vector<PopulationAggregate>{
                                      PopulationAggregate::kMean, PopulationAggregate::kMeanStd,
                                      PopulationAggregate::kWorst, PopulationAggregate::kCvar};
  for (PopulationAggregate aggregate : aggregates) {
    PopulationObjective objective = population(aggregate);
    EXPECT_DOUBLE_EQ(objective.weights()[1], 0.5);
    // Away from the start, where the bodies score differently (at x₀ every r_b is 1).
    const ObjectiveValue start = objective.Evaluate(x0, true);
    ASSERT_TRUE(start.ok) << start.message;
    const Eigen::VectorXd x = x0 - 2e-3 * start.gradient.normalized();
    const ObjectiveValue at = objective.Evaluate(x, true);
    ASSERT_TRUE(at.ok) << at.message;
    const PopulationOptions options = Options(aggregate);
    EXPECT_NEAR(at.phi, composed(x, options), 1e-12 * std::abs(at.phi));
    EXPECT_GT(*std::max_element(objective.last_scores().begin(), objective.last_scores().end()) -
                  *std::min_element(objective.last_scores().begin(), objective.last_scores().end()),
              1e-3);
    std::vector<Eigen::VectorXd> directions = {at.gradient.normalized()};
    if (!testing::SanitizedBuild()) directions.push_back(random);
    for (const Eigen::VectorXd& d : directions) {
      double best = INFINITY;
      for (double h : {1e-6, 1e-7}) {
        const double fd = (composed(x + h * d, options) - composed(x - h * d, options)) / (2 * h);
        best =
            std::min(best, std::abs(fd - at.gradient.dot(d)) /
                               std::max(std::abs(at.gradient.dot(d)), 1e-3 * at.gradient.norm()));
      }
      // 1e-4 relative: the design-gradient tests' bound (fresh solves to 1e-11).
      EXPECT_LT(best, 1e-4) << PopulationAggregateName(aggregate);
      std::cout << PopulationAggregateName(aggregate) << ": relative error " << best << "\n";
    }
  }
}

// Two "processes" in one test: two threads, each with its own PopulationObjective, meeting
// at every exchange (what MPI_Allreduce does between ranks).
class Rendezvous {
 public:
  // Adds `mine` to the other party's buffer; both return the sum.
  template <typename T, typename Combine>
  void Meet(std::vector<T>* mine, Combine combine) {
    std::unique_lock<std::mutex> lock(mutex_);
    const long round = round_;
    if (!waiting_) {
      waiting_ = true;
      first_.assign(reinterpret_cast<const unsigned char*>(mine->data()),
                    reinterpret_cast<const unsigned char*>(mine->data() + mine->size()));
      changed_.wait(lock, [&] { return round_ != round; });
      mine->assign(reinterpret_cast<const T*>(result_.data()),
                   reinterpret_cast<const T*>(result_.data() + result_.size()));
      return;
    }
    const T* other = reinterpret_cast<const T*>(first_.data());
    for (size_t i = 0; i < mine->size(); ++i) (*mine)[i] = combine(other[i], (*mine)[i]);
    result_.assign(reinterpret_cast<const unsigned char*>(mine->data()),
                   reinterpret_cast<const unsigned char*>(mine->data() + mine->size()));
    waiting_ = false;
    ++round_;
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool waiting_ = false;
  long round_ = 0;
  std::vector<unsigned char> first_, result_;
};

class TestExchange : public PopulationExchange {
 public:
  explicit TestExchange(std::shared_ptr<Rendezvous> rendezvous) : rendezvous_(rendezvous) {}
  void SumDisjoint(std::vector<double>* values) override {
    rendezvous_->Meet(values, [](double a, double b) { return a + b; });
  }
  void MaxBytes(std::vector<unsigned char>* bytes) override {
    rendezvous_->Meet(bytes, [](unsigned char a, unsigned char b) { return std::max(a, b); });
  }
  std::unique_ptr<PopulationExchange> Clone() const override {
    return std::make_unique<TestExchange>(rendezvous_);
  }

 private:
  std::shared_ptr<Rendezvous> rendezvous_;
};

// An objective whose evaluation fails, as a body whose equilibrium does not converge.
class FailingObjective : public ExtendedRosenbrock {
 public:
  FailingObjective() : ExtendedRosenbrock(6) {}
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override {
    ObjectiveValue value = ExtendedRosenbrock::Evaluate(x, with_gradient);
    value.ok = false;
    value.message = "the equilibrium did not converge in 3 Newton iterations";
    return value;
  }
  std::unique_ptr<Objective> Clone() const override { return std::make_unique<FailingObjective>(); }
};

// Bodies 0..count-1; `party` keeps the even (0) or odd (1) ones, -1 all of them.
PopulationObjective Split(int party, int count, bool failing_third,
                          std::shared_ptr<Rendezvous> rendezvous, PopulationAggregate aggregate) {
  std::vector<PopulationMember> members;
  for (int b = 0; b < count; ++b) {
    std::unique_ptr<Objective> objective;
    if (party < 0 || b % 2 == party) {
      if (failing_third && b == 2)
        objective = std::make_unique<FailingObjective>();
      else
        objective = std::make_unique<IllConditionedQuadratic>(6, 10.0 * (b + 1), b + 1);
    }
    members.push_back({"body-" + std::to_string(b), 1.0 + b, 0.5 + b, std::move(objective)});
  }
  return PopulationObjective(
      std::move(members), Options(aggregate),
      party < 0 ? nullptr : std::make_unique<TestExchange>(std::move(rendezvous)));
}

TEST(SolversPopulation, BodiesSplitOverTwoProcessesGiveTheSameBitsAsOne) {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(6, -0.3, 0.7);
  for (PopulationAggregate aggregate :
       {PopulationAggregate::kMeanStd, PopulationAggregate::kCvar}) {
    PopulationObjective whole = Split(-1, 5, false, nullptr, aggregate);
    const ObjectiveValue expected = whole.Evaluate(x, true);
    ASSERT_TRUE(expected.ok);
    auto rendezvous = std::make_shared<Rendezvous>();
    PopulationObjective even = Split(0, 5, false, rendezvous, aggregate);
    PopulationObjective odd = Split(1, 5, false, rendezvous, aggregate);
    // Copies take their own channel and keep their members: evaluated as the originals.
    std::unique_ptr<Objective> even_copy = even.Clone(), odd_copy = odd.Clone();
    ObjectiveValue on_even, on_odd, on_even_copy, on_odd_copy;
    std::thread other([&] {
      on_odd = odd.Evaluate(x, true);
      on_odd_copy = odd_copy->Evaluate(x, true);
    });
    on_even = even.Evaluate(x, true);
    on_even_copy = even_copy->Evaluate(x, true);
    other.join();
    for (const ObjectiveValue* v : {&on_even, &on_odd, &on_even_copy, &on_odd_copy}) {
      ASSERT_TRUE(v->ok) << v->message;
      EXPECT_EQ(v->phi, expected.phi);  // bit for bit: every slot is summed with zeros only
      EXPECT_EQ(v->gradient, expected.gradient);
      // The members' named terms cross the exchange too (names, weights and values).
      ASSERT_EQ(v->terms.size(), expected.terms.size());
      for (size_t t = 0; t < expected.terms.size(); ++t) {
        EXPECT_EQ(v->terms[t].name, expected.terms[t].name);
        EXPECT_EQ(v->terms[t].weight, expected.terms[t].weight);
        EXPECT_EQ(v->terms[t].value, expected.terms[t].value);
      }
    }
    ASSERT_FALSE(expected.terms.empty());
    EXPECT_EQ(even.last_scores(), whole.last_scores());
  }
}

TEST(SolversPopulation, ABodyFailingInOneProcessFailsTheEvaluationInEveryProcessNamingIt) {
  auto rendezvous = std::make_shared<Rendezvous>();
  PopulationObjective even = Split(0, 4, true, rendezvous, PopulationAggregate::kMean);
  PopulationObjective odd = Split(1, 4, true, rendezvous, PopulationAggregate::kMean);
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(6, 0.1);
  ObjectiveValue on_odd;
  std::thread other([&] { on_odd = odd.Evaluate(x, true); });
  ObjectiveValue on_even = even.Evaluate(x, true);
  other.join();
  // Body 2 lives with the even party; the odd one learns its name and its message.
  for (const ObjectiveValue* v : {&on_even, &on_odd}) {
    EXPECT_FALSE(v->ok);
    EXPECT_EQ(v->message, "body body-2: the equilibrium did not converge in 3 Newton iterations");
  }
}

}  // namespace
}  // namespace ergo
