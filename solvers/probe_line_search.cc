#include "solvers/probe_line_search.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <utility>

#include <glog/logging.h>
#include <omp.h>

#include "ergo/mesh/blas_threads.h"

namespace ergo {

ProbeLineSearch::ProbeLineSearch(ProbeOptions options)
    : options_(std::move(options)), last_accepted_(static_cast<int>(options_.moves.size()) / 2) {
  CHECK(!options_.moves.empty()) << "the probe line search needs at least one trial move";
  for (double move : options_.moves) CHECK(move > 0 && std::isfinite(move)) << move;
}

std::vector<double> ProbeLineSearch::StepLengths(const Objective& objective,
                                                 const Eigen::VectorXd& d) const {
  const double largest = objective.LargestMove(d);
  CHECK(largest > 0 && std::isfinite(largest)) << "the search direction moves no vertex";
  std::vector<double> steps;
  for (double move : options_.moves) steps.push_back(move / largest);
  return steps;
}

std::vector<int> ProbeLineSearch::ChooseProbes(long allowed) const {
  const int count = static_cast<int>(options_.moves.size());
  std::vector<int> order(count);
  for (int j = 0; j < count; ++j) order[j] = j;
  if (allowed >= count) return order;
  // Nearest to the last accepted probe first, the smaller move on ties.
  std::stable_sort(order.begin(), order.end(), [this](int a, int b) {
    return std::abs(a - last_accepted_) < std::abs(b - last_accepted_);
  });
  order.resize(static_cast<size_t>(std::max(0L, allowed)));
  std::sort(order.begin(), order.end());
  return order;
}

ProbeOutcome ProbeLineSearch::Search(const Objective& current, const Eigen::VectorXd& x, double phi,
                                     const Eigen::VectorXd& d, RunMonitor* monitor) {
  const std::vector<double> steps = StepLengths(current, d);
  const std::vector<int> chosen = ChooseProbes(monitor->RemainingEvaluations());
  const int count = static_cast<int>(chosen.size());

  struct Probe {
    std::unique_ptr<Objective> objective;
    Eigen::VectorXd x;
    ObjectiveValue value;
    bool evaluated = false;
  };
  std::vector<Probe> probes(count);
  for (int i = 0; i < count; ++i) {
    probes[i].objective = current.Clone();  // warm-started from the current design's state
    probes[i].x = x + steps[chosen[i]] * d;
  }
  std::atomic<int> next{0};
  auto work = [&]() {
    for (int i = next++; i < count; i = next++) {
      probes[i].evaluated = monitor->Evaluate(*probes[i].objective, probes[i].x,
                                              options_.gradient_at_probes, &probes[i].value);
    }
  };
  const int threads = std::min(count, options_.threads > 0 ? options_.threads : count);
  if (threads <= 1) {
    work();
  } else {
    const SingleThreadedBlas single_threaded_blas;
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&work]() {
        // The probes already occupy the cores: no OpenMP team inside each probe's assembly
        // either (affects this thread only).
        omp_set_num_threads(1);
        work();
      });
    }
    for (std::thread& thread : pool) thread.join();
  }

  ProbeOutcome outcome;
  int best = -1;
  for (int i = 0; i < count; ++i) {
    if (!probes[i].evaluated) continue;
    ++outcome.evaluated;
    if (!probes[i].value.ok) {
      ++outcome.failed;
      continue;
    }
    // Ties go to the smaller move (the earlier probe).
    if (probes[i].value.phi < phi && (best < 0 || probes[i].value.phi < probes[best].value.phi))
      best = i;
  }
  if (best < 0) return outcome;
  outcome.accepted = chosen[best];
  last_accepted_ = outcome.accepted;
  outcome.x = std::move(probes[best].x);
  outcome.value = std::move(probes[best].value);
  outcome.objective = std::move(probes[best].objective);
  return outcome;
}

}  // namespace ergo
