#include "solvers/fresh_rounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include <glog/logging.h>

namespace ergo {

RoundsResult MinimizeInRounds(Optimizer& optimizer, const RoundsProblem& problem,
                              const Eigen::VectorXd& x0, double phi0_fresh, const Budget& budget,
                              const RunControl& control, const RoundsOptions& options) {
  CHECK(problem.make_objective && problem.fresh_score);
  const auto begin = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  };
  RoundsResult out;
  out.kept_x = x0;
  out.kept_fresh_phi = phi0_fresh;
  out.kept_followed_phi = phi0_fresh;
  OptimizerResult& total = out.result;
  total.optimizer = optimizer.name();
  total.ok = true;
  total.initial_phi = phi0_fresh;
  total.best_x = x0;
  total.best_phi = phi0_fresh;
  long used = 0;  // evaluations, fresh checks included
  long newton = 0;
  int iteration_offset = 0;
  std::string reason;

  while (true) {
    const long remaining = budget.max_evaluations - used;
    if (remaining <= 1) {
      reason = "budget: " + std::to_string(budget.max_evaluations) + " evaluations";
      break;
    }
    if (control.stop && control.stop->load()) {
      reason = "interrupted";
      break;
    }
    if (budget.max_seconds > 0 && seconds() >= budget.max_seconds) {
      reason = "budget: " + std::to_string(budget.max_seconds) + " s";
      break;
    }
    // One round: the optimiser on its own path from the kept design, leaving room for the
    // fresh checks of its candidates.
    const int checks = std::max(1, options.candidates);
    Budget round = budget;
    round.max_evaluations = static_cast<int>(
        options.round_evaluations > 0
            ? std::min<long>(options.round_evaluations, remaining - checks)
            : remaining - checks);
    if (round.max_evaluations < 1) round.max_evaluations = 1;
    if (budget.max_seconds > 0) round.max_seconds = std::max(1e-3, budget.max_seconds - seconds());
    RunControl round_control = control;
    const long used_before = used;
    const double seconds_before = seconds();
    round_control.progress = [&](const IterationRecord& record) {
      IterationRecord shifted = record;
      shifted.iteration += iteration_offset;
      shifted.evaluations += used_before;
      shifted.newton_iterations += newton;
      shifted.seconds += seconds_before;
      total.history.push_back(shifted);
      return control.progress ? control.progress(shifted) : true;
    };
    std::unique_ptr<Objective> objective = problem.make_objective();
    const OptimizerResult r =
        optimizer.Minimize(*objective, out.kept_x, round, round_control);
    ++out.rounds;
    used += r.evaluations;
    newton += r.newton_iterations;
    total.failed_evaluations += r.failed_evaluations;
    if (!r.history.empty()) iteration_offset += r.history.back().iteration + 1;
    if (!r.ok) {
      reason = r.stop_reason;
      break;
    }
    // Place the round's best designs afresh; the best of them is kept if it beats the kept one.
    std::vector<double> phi, fresh;
    int best = -1;
    double best_fresh = out.kept_fresh_phi;
    for (size_t c = 0; c < r.candidates.size() && static_cast<int>(c) < checks; ++c) {
      if (control.stop && control.stop->load()) break;
      if (r.candidates[c].isApprox(out.kept_x, 0.0)) continue;  // the round's start
      const double value = problem.fresh_score(r.candidates[c]);
      ++used;
      phi.push_back(r.candidate_phi[c]);
      fresh.push_back(value);
      if (std::isfinite(value) && value < best_fresh) {
        best_fresh = value;
        best = static_cast<int>(c);
      }
    }
    if (!phi.empty()) {
      out.candidate_phi = phi;
      out.candidate_fresh_phi = fresh;
      out.kept_candidate = -1;
    }
    const bool stopped_inside =
        r.stop_reason.find("interrupt") != std::string::npos ||
        (r.stop_reason.find("budget: ") == 0 && used >= budget.max_evaluations);
    if (best < 0) {
      reason = r.stop_reason.find("interrupt") != std::string::npos
                   ? "interrupted"
                   : "no design of round " + std::to_string(out.rounds) +
                         " beat the kept one when placed afresh (round: " + r.stop_reason + ")";
      break;
    }
    // The index among the checked ones (skipped starts shift it).
    int index = 0;
    for (size_t c = 0; c < static_cast<size_t>(best); ++c)
      if (!r.candidates[c].isApprox(out.kept_x, 0.0)) ++index;
    out.kept_candidate = index;
    out.kept_x = r.candidates[best];
    out.kept_fresh_phi = best_fresh;
    out.kept_followed_phi = r.candidate_phi[best];
    out.kept_path = r.best_objective;
    if (stopped_inside) {
      reason = r.stop_reason.find("budget: ") == 0
                   ? "budget: " + std::to_string(budget.max_evaluations) + " evaluations"
                   : r.stop_reason;
      break;
    }
    // A round that ended by its own convergence test: another round from the kept design.
  }
  total.best_x = out.kept_x;
  total.best_phi = out.kept_fresh_phi;
  total.followed_phi = out.kept_followed_phi;
  total.evaluations = used;
  total.newton_iterations = newton;
  total.seconds = seconds();
  total.stop_reason = reason;
  total.candidates = {out.kept_x};
  total.candidate_phi = {out.kept_fresh_phi};
  return out;
}

}  // namespace ergo
