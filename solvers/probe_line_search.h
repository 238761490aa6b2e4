// The line search of the paper's NCG (§4.1): along a direction d, eight trial steps κ_j
// chosen so that the largest support-vertex move ‖κ_j d‖ is exactly move_j (1 µm, 10 µm,
// 0.1, 0.2, 0.5, 0.7, 1, 2 mm), evaluated in parallel threads, each on its own clone of the
// current objective (so each equilibrium is warm-started from the current design's state);
// the lowest φ is kept if it is lower than the current φ.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solvers/objective.h"
#include "solvers/optimizer.h"
#include "solvers/run_monitor.h"

namespace ergo {

struct ProbeOutcome {
  int accepted = -1;     // index into ProbeOptions::moves of the kept probe; −1: none lowered φ
  Eigen::VectorXd x;     // the kept design
  ObjectiveValue value;  // its evaluation (with ∇φ if the probes carry gradients)
  // The clone that evaluated the kept design: its warm-start cache holds that equilibrium.
  std::unique_ptr<Objective> objective;
  int evaluated = 0;  // probes evaluated (the budget may allow fewer than all)
  int failed = 0;     // probes whose evaluation failed
};

class ProbeLineSearch {
 public:
  explicit ProbeLineSearch(ProbeOptions options);

  // κ_j = move_j / LargestMove(d) for every probe (d must move some vertex).
  std::vector<double> StepLengths(const Objective& objective, const Eigen::VectorXd& d) const;

  // Probes x + κ_j d. When the budget allows fewer evaluations than probes, the probes
  // nearest (by index) to the last accepted one are evaluated.
  ProbeOutcome Search(const Objective& current, const Eigen::VectorXd& x, double phi,
                      const Eigen::VectorXd& d, RunMonitor* monitor);

  const ProbeOptions& options() const { return options_; }

 private:
  std::vector<int> ChooseProbes(long allowed) const;

  ProbeOptions options_;
  int last_accepted_;
};

}  // namespace ergo
