// PopulationObjective: one support design for several bodies — a manufacturer's one chair
// or one insole size for many people, or one person's foot at several tissue stiffnesses.
// Each member b is an Objective on the same design space (a body's DesignObjective or
// RobustDesignObjective, built on the same support and parameterisation) with a weight w_b
// (normalised so that Σ w_b = 1) and a scale s_b, its score at the start design, so that
// r_b = φ_b / s_b is 1 at the start for every body and a heavy body does not outweigh a light
// one by the size of its φ. The members are evaluated in parallel threads; each keeps its
// own equilibria and adjoint, so the gradient is exact: ∇F = Σ_b (∂F/∂r_b) ∇φ_b / s_b.
//
// The members may live in several processes (MPI ranks): a member whose objective is null
// is evaluated by another process, and the PopulationExchange brings its figures; every
// process then computes the same F and ∇F from the same bits (population_exchange.h).
//
// Aggregates of the r_b (PopulationScore gives F and ∂F/∂r_b):
//   mean      F = Σ w_b r_b
//   meanstd   F = μ + k·σ_ε, μ = Σ w_b r_b, σ_ε = √(Σ w_b (r_b − μ)² + ε²) (ε = 1e-3 keeps
//             F smooth where every body scores alike, as all do at the start: r_b = 1)
//   worst     F = T·log Σ w_b exp(r_b / T), a smooth maximum (log-sum-exp; within T·log(1/w)
//             of max r_b, → max r_b as T → 0); ∂F/∂r_b = w_b e^{r_b/T} / Σ w e^{r/T}
//   cvar      F = CVaR_α: the weighted mean of the worst 1 − α of the population (by
//             weight; the body at the boundary counts with the fraction that fits), so α = 0
//             is the mean and α → 1 the worst body; piecewise linear in r, ∂F/∂r_b the
//             body's share of the tail (exact where no two tail scores tie at the boundary)
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "solvers/objective.h"
#include "solvers/population_exchange.h"

namespace ergo {

enum class PopulationAggregate { kMean, kMeanStd, kWorst, kCvar };

// Parses mean, meanstd, worst or cvar; false otherwise.
bool ParsePopulationAggregate(const std::string& text, PopulationAggregate* aggregate);
std::string PopulationAggregateName(PopulationAggregate aggregate);

struct PopulationOptions {
  PopulationAggregate aggregate = PopulationAggregate::kMean;
  double std_weight = 1.0;    // k of meanstd
  double temperature = 0.05;  // T of worst, in units of r (5 % of a body's start score)
  double cvar_alpha = 0.5;    // α of cvar, in [0, 1): the tail is the worst 1 − α by weight
};

// F of the normalised scores r (weights w, summing to 1) and, if dF_dr is given, ∂F/∂r_b.
double PopulationScore(const std::vector<double>& r, const std::vector<double>& w,
                       const PopulationOptions& options, std::vector<double>* dF_dr);

struct PopulationMember {
  std::string name;
  double weight = 1;                     // relative; normalised over the population
  double scale = 1;                      // s_b > 0: the body's score at the start design
  std::unique_ptr<Objective> objective;  // null: evaluated by another process
};

class PopulationObjective : public Objective {
 public:
  // At least one member with an objective, all of them with the same NumParameters; positive
  // weights and scales. Members without one need `exchange` (the other processes hold them;
  // every process lists the same members in the same order).
  PopulationObjective(std::vector<PopulationMember> members, const PopulationOptions& options,
                      std::unique_ptr<PopulationExchange> exchange = nullptr);
  PopulationObjective(const PopulationObjective& other);

  int NumParameters() const override { return local().NumParameters(); }
  // The members' term names (every member has the same).
  std::vector<std::string> TermNames() const override { return local().TermNames(); }
  // F and ∇F; φ = F, its terms the weighted means of the members' r-scaled terms. Fails
  // (naming the body) if any member fails. The members' normalised scores r_b of this
  // evaluation are in last_scores().
  ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) override;
  std::unique_ptr<Objective> Clone() const override;
  double LargestMove(const Eigen::VectorXd& dx) const override;
  double BoxHalfWidthForMove(double move) const override;
  double LengthScale() const override { return local().LengthScale(); }
  std::string Describe() const override;

  int size() const { return static_cast<int>(members_.size()); }
  const PopulationMember& member(int b) const { return members_[b]; }
  const std::vector<double>& weights() const { return weights_; }
  const std::vector<double>& last_scores() const { return last_scores_; }
  // The members' own values of the last evaluation (all of them, also those of other
  // processes; without gradients).
  const std::vector<ObjectiveValue>& last_values() const { return last_values_; }

 private:
  const Objective& local() const;  // the first member evaluated here
  // Brings the other processes' members' values into `values` (see population_exchange.h).
  void Exchange(bool with_gradient, int num_parameters, std::vector<ObjectiveValue>* values);

  std::vector<PopulationMember> members_;
  std::unique_ptr<PopulationExchange> exchange_;
  std::vector<double> weights_;  // normalised
  PopulationOptions options_;
  std::vector<double> last_scores_;
  std::vector<ObjectiveValue> last_values_;
};

}  // namespace ergo
