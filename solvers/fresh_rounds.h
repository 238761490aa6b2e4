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
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solvers/objective.h"
#include "solvers/optimizer.h"

namespace ergo {

struct RoundsOptions {
  int round_evaluations = 0;  // evaluations per round; 0: one round with the whole budget
  int candidates = 3;         // a round's best designs placed afresh after it
};

// What the driver needs from the design problem.
struct RoundsProblem {
  // An objective whose evaluations follow their own path from the body placed afresh at the
  // first design evaluated.
  std::function<std::unique_ptr<Objective>()> make_objective;
  // φ of x with the body placed afresh (the score kept); NaN if the equilibrium fails.
  std::function<double(const Eigen::VectorXd& x)> fresh_score;
};

struct RoundsResult {
  OptimizerResult result;  // all rounds together: counts (fresh checks included), history
  Eigen::VectorXd kept_x;  // the design with the best fresh score (x₀ if none beat it)
  double kept_fresh_phi = 0;
  double kept_followed_phi = 0;  // the optimiser's own value there (its path), or φ₀
  // The round's objective as it stood at its best design (its path's equilibria): where the
  // kept design can be evaluated on the optimiser's path. Null if x₀ was kept.
  std::shared_ptr<Objective> kept_path;
  // The designs checked after the last round that produced candidates: the optimiser's
  // values and the fresh ones, and which was kept (-1: none beat the start).
  std::vector<double> candidate_phi, candidate_fresh_phi;
  int kept_candidate = -1;
  int rounds = 0;
};

// Runs `optimizer` from x0 (fresh score phi0_fresh) in rounds within `budget`; control's
// stop flag and progress callback apply throughout (history iterations run on across rounds).
RoundsResult MinimizeInRounds(Optimizer& optimizer, const RoundsProblem& problem,
                              const Eigen::VectorXd& x0, double phi0_fresh, const Budget& budget,
                              const RunControl& control, const RoundsOptions& options);

}  // namespace ergo
