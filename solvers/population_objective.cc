#include "solvers/population_objective.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include <glog/logging.h>

#include "ergo/design/placement_checks.h"

namespace ergo {
namespace {

constexpr double kStdSmoothing = 1e-3;  // ε of σ_ε, in units of r

}  // namespace

bool ParsePopulationAggregate(const std::string& text, PopulationAggregate* aggregate) {
  if (text == "mean")
    *aggregate = PopulationAggregate::kMean;
  else if (text == "meanstd")
    *aggregate = PopulationAggregate::kMeanStd;
  else if (text == "worst")
    *aggregate = PopulationAggregate::kWorst;
  else if (text == "cvar")
    *aggregate = PopulationAggregate::kCvar;
  else
    return false;
  return true;
}

std::string PopulationAggregateName(PopulationAggregate aggregate) {
  switch (aggregate) {
    case PopulationAggregate::kMean:
      return "mean";
    case PopulationAggregate::kMeanStd:
      return "meanstd";
    case PopulationAggregate::kWorst:
      return "worst";
    case PopulationAggregate::kCvar:
      return "cvar";
  }
  return "?";
}

double PopulationScore(const std::vector<double>& r, const std::vector<double>& w,
                       const PopulationOptions& options, std::vector<double>* dF_dr) {
  CHECK_EQ(r.size(), w.size());
  CHECK(!r.empty());
  const size_t n = r.size();
  if (dF_dr) dF_dr->assign(n, 0.0);
  double mean = 0;
  for (size_t b = 0; b < n; ++b) mean += w[b] * r[b];
  switch (options.aggregate) {
    case PopulationAggregate::kMean:
      if (dF_dr) *dF_dr = w;
      return mean;
    case PopulationAggregate::kMeanStd: {
      double variance = 0;
      for (size_t b = 0; b < n; ++b) variance += w[b] * (r[b] - mean) * (r[b] - mean);
      const double sigma = std::sqrt(variance + kStdSmoothing * kStdSmoothing);
      // ∂σ/∂r_b = w_b (r_b − μ)/σ (the μ terms cancel: Σ w (r − μ) = 0).
      if (dF_dr)
        for (size_t b = 0; b < n; ++b)
          (*dF_dr)[b] = w[b] + options.std_weight * w[b] * (r[b] - mean) / sigma;
      return mean + options.std_weight * sigma;
    }
    case PopulationAggregate::kWorst: {
      const double t = options.temperature;
      const double top = *std::max_element(r.begin(), r.end());  // shift: no overflow
      double sum = 0;
      std::vector<double> terms(n);
      for (size_t b = 0; b < n; ++b) sum += terms[b] = w[b] * std::exp((r[b] - top) / t);
      if (dF_dr)
        for (size_t b = 0; b < n; ++b) (*dF_dr)[b] = terms[b] / sum;
      return top + t * std::log(sum);
    }
    case PopulationAggregate::kCvar: {
      const double tail = 1.0 - options.cvar_alpha;
      std::vector<size_t> order(n);
      std::iota(order.begin(), order.end(), size_t{0});
      std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return r[a] > r[b]; });
      double taken = 0, value = 0;
      for (size_t b : order) {
        const double take = std::min(w[b], tail - taken);
        if (!(take > 0)) break;
        value += take * r[b];
        if (dF_dr) (*dF_dr)[b] = take / tail;
        taken += take;
      }
      return value / tail;
    }
  }
  return mean;
}

PopulationObjective::PopulationObjective(std::vector<PopulationMember> members,
                                         const PopulationOptions& options,
                                         std::unique_ptr<PopulationExchange> exchange)
    : members_(std::move(members)), exchange_(std::move(exchange)), options_(options) {
  CHECK(!members_.empty());
  double total = 0;
  const Objective& first = local();
  for (const PopulationMember& m : members_) {
    CHECK(m.objective || exchange_) << m.name << ": evaluated nowhere";
    if (m.objective) {
      CHECK_EQ(m.objective->NumParameters(), first.NumParameters()) << m.name;
      CHECK(m.objective->TermNames() == first.TermNames()) << m.name << ": other objective terms";
    }
    CHECK(m.weight > 0 && m.scale > 0) << m.name;
    total += m.weight;
  }
  for (const PopulationMember& m : members_) weights_.push_back(m.weight / total);
  CHECK(options_.temperature > 0);
  CHECK(options_.cvar_alpha >= 0 && options_.cvar_alpha < 1);
}

PopulationObjective::PopulationObjective(const PopulationObjective& other)
    : exchange_(other.exchange_ ? other.exchange_->Clone() : nullptr),
      weights_(other.weights_),
      options_(other.options_),
      last_scores_(other.last_scores_),
      last_values_(other.last_values_) {
  for (const PopulationMember& m : other.members_)
    members_.push_back({m.name, m.weight, m.scale, m.objective ? m.objective->Clone() : nullptr});
}

const Objective& PopulationObjective::local() const {
  for (const PopulationMember& m : members_)
    if (m.objective) return *m.objective;
  LOG(FATAL) << "a population objective with no member evaluated in this process";
  return *members_.front().objective;
}

namespace {

// Per body in the exchanged buffer: status (1 ok, 2 failed), φ, Newton iterations,
// seconds, each term's weight and value (in TermNames() order), the timing entries, then the
// gradient.
constexpr int kHeader = 4;
constexpr size_t kMessageBytes = 480;

// The time split's entry names, in ForEachTimingEntry's order (the slots after the header).
const std::vector<std::string>& TimingNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    ForEachTimingEntry(
        EvaluationTiming(), [&](const char* name, double) { list.push_back(name); },
        [&](const char* name, long) { list.push_back(name); });
    return list;
  }();
  return names;
}

}  // namespace

void PopulationObjective::Exchange(bool with_gradient, int num_parameters,
                                   std::vector<ObjectiveValue>* values) {
  const int count = size();
  const std::vector<std::string>& names = TimingNames();
  const int timing_entries = static_cast<int>(names.size());
  const std::vector<std::string> term_names = TermNames();
  const int term_slots = 2 * static_cast<int>(term_names.size());
  const int timing_start = kHeader + term_slots, gradient_start = timing_start + timing_entries;
  const size_t stride = gradient_start + (with_gradient ? num_parameters : 0);
  std::vector<double> buffer(stride * count, 0.0);
  for (int b = 0; b < count; ++b) {
    if (!members_[b].objective) continue;
    const ObjectiveValue& v = (*values)[b];
    double* slot = buffer.data() + stride * b;
    slot[0] = v.ok ? 1 : 2;
    slot[1] = v.phi, slot[2] = v.newton_iterations, slot[3] = v.seconds;
    for (size_t t = 0; t < term_names.size(); ++t) {
      slot[kHeader + 2 * t] = v.ok ? v.terms.at(t).weight : 0.0;
      slot[kHeader + 2 * t + 1] = v.ok ? v.terms.at(t).value : 0.0;
    }
    int k = timing_start;
    ForEachTimingEntry(
        v.timing, [&](const char*, double x) { slot[k++] = x; },
        [&](const char*, long x) { slot[k++] = static_cast<double>(x); });
    if (with_gradient && v.ok)
      Eigen::Map<Eigen::VectorXd>(slot + gradient_start, num_parameters) = v.gradient;
  }
  exchange_->SumDisjoint(&buffer);
  bool any_failed = false;
  for (int b = 0; b < count; ++b) {
    const double* slot = buffer.data() + stride * b;
    ObjectiveValue& v = (*values)[b];
    if (members_[b].objective) {
      any_failed = any_failed || !v.ok;
      continue;
    }
    CHECK(slot[0] == 1 || slot[0] == 2) << "body " << members_[b].name << " evaluated nowhere";
    v.ok = slot[0] == 1;
    any_failed = any_failed || !v.ok;
    v.phi = slot[1], v.newton_iterations = static_cast<int>(slot[2]), v.seconds = slot[3];
    v.terms.clear();
    if (v.ok)
      for (size_t t = 0; t < term_names.size(); ++t)
        v.terms.push_back({term_names[t], slot[kHeader + 2 * t], slot[kHeader + 2 * t + 1]});
    for (int k = 0; k < timing_entries; ++k)
      SetTimingEntry(names[k], slot[timing_start + k], &v.timing);
    if (with_gradient && v.ok)
      v.gradient = Eigen::Map<const Eigen::VectorXd>(slot + gradient_start, num_parameters);
    v.message = v.ok ? "ok" : "";
  }
  if (!any_failed) return;  // every process knows this from the same sums
  std::vector<unsigned char> bytes(kMessageBytes * count, 0);
  for (int b = 0; b < count; ++b) {
    if (!members_[b].objective || (*values)[b].ok) continue;
    const std::string& message = (*values)[b].message;
    std::copy_n(message.begin(), std::min(message.size(), kMessageBytes - 1),
                bytes.begin() + static_cast<long>(kMessageBytes * b));
  }
  exchange_->MaxBytes(&bytes);
  for (int b = 0; b < count; ++b) {
    if (members_[b].objective || (*values)[b].ok) continue;
    const char* text = reinterpret_cast<const char*>(bytes.data() + kMessageBytes * b);
    (*values)[b].message = std::string(text, strnlen(text, kMessageBytes));
  }
}

ObjectiveValue PopulationObjective::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  const int count = size();
  std::vector<ObjectiveValue> values(static_cast<size_t>(count));
  std::vector<int> here;
  for (int b = 0; b < count; ++b)
    if (members_[b].objective) here.push_back(b);
  ForEachInParallel(static_cast<int>(here.size()), [&](int i) {
    values[here[i]] = members_[here[i]].objective->Evaluate(x, with_gradient);
  });
  if (exchange_) Exchange(with_gradient, static_cast<int>(x.size()), &values);
  ObjectiveValue out;
  for (const ObjectiveValue& v : values) {
    out.newton_iterations += v.newton_iterations;
    out.seconds = std::max(out.seconds, v.seconds);  // side by side: the slowest
    out.timing += v.timing;
  }
  last_values_ = values;
  for (ObjectiveValue& v : last_values_) v.gradient.resize(0);
  for (int b = 0; b < count; ++b) {
    if (!values[b].ok) {
      out.ok = false;
      out.message = "body " + members_[b].name + ": " + values[b].message;
      return out;
    }
  }
  std::vector<double> r(static_cast<size_t>(count));
  for (int b = 0; b < count; ++b) r[b] = values[b].phi / members_[b].scale;
  std::vector<double> dF_dr;
  out.phi = PopulationScore(r, weights_, options_, &dF_dr);
  for (int b = 0; b < count; ++b)
    AddScaledTerms(values[b].terms, weights_[b] / members_[b].scale, &out.terms);
  if (with_gradient) {
    out.gradient = Eigen::VectorXd::Zero(x.size());
    for (int b = 0; b < count; ++b)
      if (dF_dr[b] != 0) out.gradient += (dF_dr[b] / members_[b].scale) * values[b].gradient;
  }
  last_scores_ = r;
  out.ok = true;
  out.message = "ok";
  return out;
}

std::unique_ptr<Objective> PopulationObjective::Clone() const {
  return std::make_unique<PopulationObjective>(*this);
}

double PopulationObjective::LargestMove(const Eigen::VectorXd& dx) const {
  return local().LargestMove(dx);  // one design space for all
}

double PopulationObjective::BoxHalfWidthForMove(double move) const {
  return local().BoxHalfWidthForMove(move);
}

std::string PopulationObjective::Describe() const {
  std::string text =
      PopulationAggregateName(options_.aggregate) + " over " + std::to_string(size()) + " bodies (";
  for (int b = 0; b < size(); ++b) text += (b ? ", " : "") + members_[b].name;
  return text + ")";
}

}  // namespace ergo
