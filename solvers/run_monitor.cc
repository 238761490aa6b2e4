#include "solvers/run_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

constexpr size_t kRemembered = 4;  // exact repeats: NLopt round restarts, Ceres' first call
constexpr size_t kLogged = 256;    // enough for a Ceres line search and its iterate
constexpr size_t kCandidates = 4;  // designs kept for the caller's fresh check

bool SameDesign(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.array() == b.array()).all();
}

}  // namespace

RunMonitor::RunMonitor(std::string optimizer, const Budget& budget, const RunControl& control)
    : optimizer_(std::move(optimizer)),
      budget_(budget),
      control_(control),
      start_(std::chrono::steady_clock::now()) {}

double RunMonitor::Seconds() const { return SecondsSince(start_); }

bool RunMonitor::StopLocked(const std::string& reason) {
  if (stop_reason_.empty()) stop_reason_ = reason;
  return true;
}

bool RunMonitor::AdmitLocked() {
  if (!stop_reason_.empty()) return false;
  if (control_.stop && control_.stop->load()) return !StopLocked("interrupted");
  if (started_ >= budget_.max_evaluations) {
    return !StopLocked("budget: " + std::to_string(budget_.max_evaluations) + " evaluations");
  }
  if (budget_.max_seconds > 0 && Seconds() >= budget_.max_seconds)
    return !StopLocked(TimeBudgetReason(budget_.max_seconds));
  return true;
}

const ObjectiveValue* RunMonitor::RememberedLocked(const Eigen::VectorXd& x,
                                                   bool with_gradient) const {
  auto usable = [&](const ObjectiveValue& value) {
    return !with_gradient || value.gradient.size() == x.size();
  };
  if (has_best_ && SameDesign(best_.x, x) && usable(best_value_)) return &best_value_;
  for (const auto& [remembered_x, value] : remembered_) {
    if (SameDesign(remembered_x, x) && usable(value)) return &value;
  }
  return nullptr;
}

bool RunMonitor::Evaluate(Objective& objective, const Eigen::VectorXd& x, bool with_gradient,
                          ObjectiveValue* value) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (const ObjectiveValue* remembered = RememberedLocked(x, with_gradient)) {
      *value = *remembered;
      return true;
    }
    if (!AdmitLocked()) {
      *value = ObjectiveValue();
      value->message = "refused: " + stop_reason_;
      return false;
    }
    ++started_;
  }
  ObjectiveValue v = objective.Evaluate(x, with_gradient);
  if (v.ok && !std::isfinite(v.phi)) {  // an Objective must not do this; never report it
    v.ok = false;
    v.message = "non-finite φ";
  }
  // A likely new best: keep the objective's state there (cloned before anyone else uses it).
  std::shared_ptr<Objective> snapshot;
  if (v.ok) {
    bool better;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      better = !has_best_ || v.phi < best_.phi;
    }
    if (better) snapshot = objective.Clone();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++completed_;
  newton_iterations_ += v.newton_iterations;
  timing_ += v.timing;
  if (!v.ok) ++failed_;
  if (v.ok) {
    Logged entry{x, v.phi, v.terms,
                 with_gradient && v.gradient.size() == x.size() ? v.gradient.norm() : -1.0};
    if (!has_best_ || v.phi < best_.phi) {
      best_ = entry;
      best_value_ = v;
      has_best_ = true;
      best_objective_ = snapshot ? std::move(snapshot) : objective.Clone();
    }
    // The best few distinct designs, for the caller's fresh check of what it keeps.
    const bool seen = std::any_of(candidates_.begin(), candidates_.end(),
                                  [&](const Logged& c) { return SameDesign(c.x, x); });
    if (!seen) {
      candidates_.push_back(entry);
      std::sort(candidates_.begin(), candidates_.end(),
                [](const Logged& a, const Logged& b) { return a.phi < b.phi; });
      if (candidates_.size() > kCandidates) candidates_.pop_back();
    }
    log_.push_back(std::move(entry));
    if (log_.size() > kLogged) log_.pop_front();
    remembered_.emplace_back(x, v);
    if (remembered_.size() > kRemembered) remembered_.pop_front();
  }
  if (control_.on_evaluation) control_.on_evaluation(x, v);
  *value = std::move(v);
  return true;
}

long RunMonitor::RemainingEvaluations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::max(0L, budget_.max_evaluations - started_);
}

bool RunMonitor::ShouldStop() {
  std::lock_guard<std::mutex> lock(mutex_);
  return !AdmitLocked();
}

bool RunMonitor::stopped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return !stop_reason_.empty();
}

std::string RunMonitor::stop_reason() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stop_reason_;
}

void RunMonitor::RequestStop(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  StopLocked(reason);
}

void RunMonitor::AddIteration(IterationRecord record) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    record.evaluations = completed_;
    record.newton_iterations = newton_iterations_;
    record.timing = timing_;
  }
  record.seconds = Seconds();
  history_.push_back(record);
  if (control_.progress && !control_.progress(record)) RequestStop("interrupted");
}

RunMonitor::Logged RunMonitor::Lookup(const Eigen::VectorXd& x, bool* exact) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const Logged* nearest = nullptr;
  double distance = std::numeric_limits<double>::infinity();
  for (auto it = log_.rbegin(); it != log_.rend(); ++it) {
    if (SameDesign(it->x, x)) {
      if (exact) *exact = true;
      return *it;
    }
    const double d = (it->x - x).lpNorm<Eigen::Infinity>();
    if (d < distance) {
      distance = d;
      nearest = &*it;
    }
  }
  if (exact) *exact = false;
  return nearest ? *nearest : best_;
}

bool RunMonitor::has_best() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return has_best_;
}

RunMonitor::Logged RunMonitor::best() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return best_;
}

long RunMonitor::evaluations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return completed_;
}

OptimizerResult RunMonitor::Finish(const std::string& optimizer_reason) const {
  OptimizerResult result;
  result.seconds = Seconds();
  std::lock_guard<std::mutex> lock(mutex_);
  result.optimizer = optimizer_;
  result.ok = has_best_;
  if (has_best_) {
    result.best_x = best_.x;
    result.best_phi = best_.phi;
    result.best_terms = best_.terms;
    result.best_objective = best_objective_;
    for (const Logged& c : candidates_) {
      result.candidates.push_back(c.x);
      result.candidate_phi.push_back(c.phi);
    }
  }
  result.initial_phi =
      history_.empty() ? std::numeric_limits<double>::quiet_NaN() : history_.front().phi;
  result.history = history_;
  result.stop_reason = stop_reason_.empty() ? optimizer_reason : stop_reason_;
  result.evaluations = completed_;
  result.failed_evaluations = failed_;
  result.newton_iterations = newton_iterations_;
  result.timing = timing_;
  return result;
}

}  // namespace ergo
