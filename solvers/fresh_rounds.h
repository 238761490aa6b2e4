// Optimisation in rounds re-anchored on fresh placements (DESIGN.md §8). Contact of a soft
// body with a sculpted, frictionless support has several equilibria close together (a patch
// of tissue may rest a fraction of a millimetre to either side of a ridge, within 1e-5 of
// the energy of the other state), so the score of a design depends on where the body came
// from: an optimiser that warm-starts every equilibrium from the last one follows one branch
// smoothly and can drift into gains a person placed afresh does not get; one that places the
// body afresh every time sees the branch chosen anew at every design, a noisy function its
// line searches stall on. Rounds take the best of both: each round runs the optimiser for a
// bounded number of evaluations on its own path, which starts with the body placed afresh
// at the round's start design; the round's best few designs are then placed afresh, and the
// best of those starts the next round and is the design kept. No gain survives that a fresh
// placement does not confirm, and the path cannot drift for longer than a round.
//
// A round depends only on the design it starts from and the budget left, so the state
// between rounds (RoundsState) is a checkpoint: a run resumed from it ends exactly where the
// uninterrupted run would (evaluation budgets; a wall-clock budget is not reproducible).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/objective.h"
#include "solvers/optimizer.h"

namespace ergo {

// Everything a run in rounds carries from one round to the next.
struct RoundsState {
  Eigen::VectorXd kept_x;        // the design kept so far (x₀ at the start)
  double kept_fresh_phi = 0;     // its score placed afresh
  double kept_followed_phi = 0;  // the optimiser's own value there (φ₀ at the start)
  long evaluations = 0;          // spent, fresh checks included
  long newton_iterations = 0;
  long failed_evaluations = 0;
  EvaluationTiming timing;  // of those evaluations, fresh checks included
  int rounds = 0;
  int next_iteration = 0;  // the history's next iteration number
  double seconds = 0;      // wall time spent
  std::vector<IterationRecord> history;
  // The fresh checks of the round that gave the kept design (else of the first round).
  std::vector<double> candidate_phi, candidate_fresh_phi;
  int kept_candidate = -1;  // index into them, -1: nothing beat the start
  bool finished = false;    // the run ended (with `stop_reason`); nothing to resume
  std::string stop_reason;
};

struct RoundsOptions {
  int round_evaluations = 0;  // evaluations per round; 0: one round with the whole budget
  int candidates = 3;         // a round's best designs placed afresh after it
  // Under a time budget: the wall time of one fresh score as the caller measured it (φ₀'s),
  // so that a round leaves room for its checks inside the budget; later rounds use the mean
  // of the checks made. 0: unknown (the first round's checks may then end past the budget).
  double fresh_score_seconds = 0;
  // Called after every round with the state a resumed run would start from (a checkpoint).
  std::function<void(const RoundsState&)> on_round;
};

// What the driver needs from the design problem.
struct RoundsProblem {
  // An objective whose evaluations follow their own path from the body placed afresh at the
  // first design evaluated.
  std::function<std::unique_ptr<Objective>()> make_objective;
  // φ of x with the body placed afresh (the score kept); NaN if the equilibrium fails. Adds
  // the evaluation's time split to *timing.
  std::function<double(const Eigen::VectorXd& x, EvaluationTiming* timing)> fresh_score;
};

struct RoundsResult {
  OptimizerResult result;  // all rounds together: counts and time split (fresh checks
                           // included), history
  Eigen::VectorXd kept_x;  // the design with the best fresh score (x₀ if none beat it)
  double kept_fresh_phi = 0;
  double kept_followed_phi = 0;  // the optimiser's own value there (its path), or φ₀
  // The round's objective as it stood at its best design (its path's equilibria): where the
  // kept design can be evaluated on the optimiser's path. Null if x₀ was kept or the kept
  // design came from a round run before a resume.
  std::shared_ptr<Objective> kept_path;
  std::vector<double> candidate_phi, candidate_fresh_phi;  // as RoundsState
  int kept_candidate = -1;
  int rounds = 0;
};

// Runs `optimizer` from x0 (fresh score phi0_fresh) in rounds within `budget`; control's
// stop flag and progress callback apply throughout (history iterations run on across
// rounds). With `resume`, continues from that state instead (x0 and phi0_fresh unused).
RoundsResult MinimizeInRounds(Optimizer& optimizer, const RoundsProblem& problem,
                              const Eigen::VectorXd& x0, double phi0_fresh, const Budget& budget,
                              const RunControl& control, const RoundsOptions& options,
                              const RoundsState* resume = nullptr);

}  // namespace ergo
