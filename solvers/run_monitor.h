// RunMonitor: the single gate every evaluation of one optimiser run passes through. It
// enforces the Budget and the stop flag, counts every φ evaluation (probes and failures
// included), its Newton iterations and its time split, keeps the best design that was evaluated
// successfully, and builds the history — so that what a run reports is what was evaluated,
// whatever the optimiser believes internally. Thread-safe: parallel probes share one.
#pragma once

#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/objective.h"
#include "solvers/optimizer.h"

namespace ergo {

class RunMonitor {
 public:
  RunMonitor(std::string optimizer, const Budget& budget, const RunControl& control);

  // Evaluates objective at x if the budget and the stop flag allow it. Returns false
  // without evaluating (and *value.ok = false, message "refused: <reason>") otherwise.
  // A request for exactly a design evaluated before (bit for bit, gradient included when
  // asked for) is answered from memory and not counted: it is not a new evaluation.
  bool Evaluate(Objective& objective, const Eigen::VectorXd& x, bool with_gradient,
                ObjectiveValue* value);

  // Evaluations the budget still allows (not counting ones in flight).
  long RemainingEvaluations() const;
  // True when the run must end: interrupted, evaluation budget used up or time is over.
  // The first such reason is kept as the stop reason.
  bool ShouldStop();
  bool stopped() const;
  std::string stop_reason() const;
  // Stops with `reason` unless a reason is already set.
  void RequestStop(const std::string& reason);

  // Appends a history entry, filling in evaluations, Newton iterations, seconds and the time
  // split so far, and calls the progress callback (which may stop the run: "interrupted").
  void AddIteration(IterationRecord record);
  const std::vector<IterationRecord>& history() const { return history_; }

  // A successfully evaluated design's values, looked up by the exact design vector.
  struct Logged {
    Eigen::VectorXd x;
    double phi = 0;
    ObjectiveTerms terms;
    double gradient_norm = -1;  // −1: evaluated without gradient
  };
  // The logged evaluation at exactly x, else the logged one nearest to x (∞-norm);
  // *exact says which.
  Logged Lookup(const Eigen::VectorXd& x, bool* exact = nullptr) const;

  bool has_best() const;
  Logged best() const;
  long evaluations() const;
  double Seconds() const;

  // The result: best design, counts, history; stop_reason = the monitor's reason if any
  // (budget, interruption), else `optimizer_reason`.
  OptimizerResult Finish(const std::string& optimizer_reason) const;

 private:
  bool AdmitLocked();
  bool StopLocked(const std::string& reason);
  const ObjectiveValue* RememberedLocked(const Eigen::VectorXd& x, bool with_gradient) const;

  const std::string optimizer_;
  const Budget budget_;
  const RunControl control_;
  const std::chrono::steady_clock::time_point start_;

  mutable std::mutex mutex_;
  long started_ = 0;    // evaluations admitted
  long completed_ = 0;  // evaluations finished (the count reported)
  long failed_ = 0;
  long newton_iterations_ = 0;
  EvaluationTiming timing_;  // of the completed evaluations
  std::string stop_reason_;
  bool has_best_ = false;
  Logged best_;
  ObjectiveValue best_value_;                  // with its gradient, if evaluated with one
  std::shared_ptr<Objective> best_objective_;  // cloned right after evaluating best_
  std::vector<Logged> candidates_;             // the best few distinct designs, best first
  // Recent successful evaluations with everything (answers exact repeats).
  std::deque<std::pair<Eigen::VectorXd, ObjectiveValue>> remembered_;
  std::deque<Logged> log_;  // recent successful evaluations, for Lookup
  std::vector<IterationRecord> history_;
};

}  // namespace ergo
