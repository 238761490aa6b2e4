#include "solvers/fresh_rounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include <glog/logging.h>

#include "ergo/mesh/seconds_since.h"

namespace ergo {

RoundsResult MinimizeInRounds(Optimizer& optimizer, const RoundsProblem& problem,
                              const Eigen::VectorXd& x0, double phi0_fresh, const Budget& budget,
                              const RunControl& control, const RoundsOptions& options,
                              const RoundsState* resume) {
  CHECK(problem.make_objective && problem.fresh_score);
  const auto begin = std::chrono::steady_clock::now();
  RoundsState state;
  if (resume) {
    state = *resume;
  } else {
    state.kept_x = x0;
    state.kept_fresh_phi = phi0_fresh;
    state.kept_followed_phi = phi0_fresh;
  }
  const double seconds_before = state.seconds;
  auto seconds = [&] { return seconds_before + SecondsSince(begin); };
  RoundsResult out;
  const double initial_phi =
      resume && !resume->history.empty() ? resume->history.front().phi : phi0_fresh;

  // The mean wall time of a fresh check, to keep the checks inside a time budget.
  double check_seconds = options.fresh_score_seconds;
  int checks_timed = 0;

  while (!state.finished) {
    const long remaining = budget.max_evaluations - state.evaluations;
    // A small budget keeps most of itself for the optimiser: at most a quarter for checks.
    const int checks =
        static_cast<int>(std::clamp<long>(options.candidates, 1, std::max<long>(1, remaining / 4)));
    if (remaining <= 1) {
      state.finished = true;
      state.stop_reason = "budget: " + std::to_string(budget.max_evaluations) + " evaluations";
      break;
    }
    if (control.stop && control.stop->load()) {
      state.stop_reason = "interrupted";
      break;  // not finished: a resume continues from here
    }
    // The round needs time for at least one evaluation besides its checks.
    if (budget.max_seconds > 0 && seconds() + (checks + 1) * check_seconds >= budget.max_seconds) {
      state.finished = true;
      state.stop_reason = TimeBudgetReason(budget.max_seconds);
      break;
    }
    // One round: the optimiser on its own path from the kept design, leaving room for the
    // fresh checks of its candidates.
    Budget round = budget;
    round.max_evaluations = static_cast<int>(
        std::max<long>(1, options.round_evaluations > 0
                              ? std::min<long>(options.round_evaluations, remaining - checks)
                              : remaining - checks));
    if (budget.max_seconds > 0)
      round.max_seconds = std::max(1e-3, budget.max_seconds - seconds() - checks * check_seconds);
    RunControl round_control = control;
    const long used_before = state.evaluations, newton_before = state.newton_iterations;
    const EvaluationTiming timing_before = state.timing;
    const int iteration_before = state.next_iteration;
    const double round_start = seconds();
    round_control.progress = [&](const IterationRecord& record) {
      IterationRecord shifted = record;
      shifted.iteration += iteration_before;
      shifted.evaluations += used_before;
      shifted.newton_iterations += newton_before;
      shifted.seconds += round_start;
      shifted.timing += timing_before;
      shifted.kept_fresh_phi = state.kept_fresh_phi;
      state.history.push_back(shifted);
      return control.progress ? control.progress(shifted) : true;
    };
    std::unique_ptr<Objective> objective = problem.make_objective();
    const OptimizerResult r = optimizer.Minimize(*objective, state.kept_x, round, round_control);
    ++state.rounds;
    state.evaluations += r.evaluations;
    state.newton_iterations += r.newton_iterations;
    state.failed_evaluations += r.failed_evaluations;
    state.timing += r.timing;
    if (!r.history.empty())
      state.next_iteration = iteration_before + r.history.back().iteration + 1;
    const bool interrupted = r.stop_reason.find("interrupt") != std::string::npos;
    if (!r.ok) {
      state.finished = !interrupted;
      state.stop_reason = r.stop_reason;
      break;
    }
    // Place the round's best designs afresh; the best of them is kept if it beats the kept one.
    std::vector<double> phi, fresh;
    int best = -1, best_checked = -1;
    double best_fresh = state.kept_fresh_phi;
    bool placed = false;  // a check reached equilibrium at every placement
    for (size_t c = 0; c < r.candidates.size() && static_cast<int>(phi.size()) < checks; ++c) {
      if (control.stop && control.stop->load()) break;
      if (r.candidates[c] == state.kept_x) continue;  // the round's start
      // Past the time budget only one design is placed afresh (else the round is lost): the
      // round's best, or the next if the body found no equilibrium on it.
      if (placed && budget.max_seconds > 0 && seconds() + check_seconds > budget.max_seconds) break;
      const double check_start = seconds();
      const double value = problem.fresh_score(r.candidates[c], &state.timing);
      check_seconds =
          (check_seconds * checks_timed + (seconds() - check_start)) / (checks_timed + 1);
      ++checks_timed;
      ++state.evaluations;
      phi.push_back(r.candidate_phi[c]);
      fresh.push_back(value);
      placed = placed || std::isfinite(value);
      if (std::isfinite(value) && value < best_fresh) {
        best_fresh = value;
        best = static_cast<int>(c);
        best_checked = static_cast<int>(phi.size()) - 1;
      }
    }
    // Report the checks of the round that gave the kept design (or the first round's).
    if (!phi.empty() && (best >= 0 || state.candidate_phi.empty())) {
      state.candidate_phi = phi;
      state.candidate_fresh_phi = fresh;
      state.kept_candidate = best_checked;
    }
    if (best >= 0) {
      state.kept_x = r.candidates[best];
      state.kept_fresh_phi = best_fresh;
      state.kept_followed_phi = r.candidate_phi[best];
      out.kept_path = r.best_objective;
    }
    if (interrupted || (control.stop && control.stop->load())) {
      state.stop_reason = "interrupted";
      break;  // a resume repeats nothing: this round's outcome is in the state
    }
    if (best < 0) {
      state.finished = true;
      state.stop_reason = "no design of round " + std::to_string(state.rounds) +
                          " beat the kept one when placed afresh (round: " + r.stop_reason + ")";
    } else if (state.evaluations >= budget.max_evaluations - 1) {
      state.finished = true;
      state.stop_reason = "budget: " + std::to_string(budget.max_evaluations) + " evaluations";
    } else if (r.stop_reason.find("budget: ") == 0 &&
               r.stop_reason.find(" s") != std::string::npos) {
      state.finished = true;
      state.stop_reason = TimeBudgetReason(budget.max_seconds);  // not the round's share
    }
    state.seconds = seconds();
    if (options.on_round) options.on_round(state);
    // A round that ended by its own convergence test or its share of the budget: another
    // round from the kept design.
  }
  state.seconds = seconds();

  OptimizerResult& total = out.result;
  total.optimizer = optimizer.name();
  total.ok = true;
  total.initial_phi = initial_phi;
  total.best_x = state.kept_x;
  total.best_phi = state.kept_fresh_phi;
  total.followed_phi = state.kept_followed_phi;
  total.candidates = {state.kept_x};
  total.candidate_phi = {state.kept_fresh_phi};
  total.history = state.history;
  total.stop_reason = state.stop_reason;
  total.evaluations = state.evaluations;
  total.failed_evaluations = state.failed_evaluations;
  total.newton_iterations = state.newton_iterations;
  total.timing = state.timing;
  total.seconds = state.seconds;
  out.kept_x = state.kept_x;
  out.kept_fresh_phi = state.kept_fresh_phi;
  out.kept_followed_phi = state.kept_followed_phi;
  out.candidate_phi = state.candidate_phi;
  out.candidate_fresh_phi = state.candidate_fresh_phi;
  out.kept_candidate = state.kept_candidate;
  out.rounds = state.rounds;
  return out;
}

}  // namespace ergo
