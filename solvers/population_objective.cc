#include "solvers/population_objective.h"

#include <algorithm>
#include <cmath>
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
  }
  return mean;
}

PopulationObjective::PopulationObjective(std::vector<PopulationMember> members,
                                         const PopulationOptions& options)
    : members_(std::move(members)), options_(options) {
  CHECK(!members_.empty());
  double total = 0;
  for (const PopulationMember& m : members_) {
    CHECK(m.objective) << m.name;
    CHECK_EQ(m.objective->NumParameters(), members_.front().objective->NumParameters()) << m.name;
    CHECK(m.weight > 0 && m.scale > 0) << m.name;
    total += m.weight;
  }
  for (const PopulationMember& m : members_) weights_.push_back(m.weight / total);
  CHECK(options_.temperature > 0);
}

PopulationObjective::PopulationObjective(const PopulationObjective& other)
    : weights_(other.weights_), options_(other.options_), last_scores_(other.last_scores_) {
  for (const PopulationMember& m : other.members_)
    members_.push_back({m.name, m.weight, m.scale, m.objective->Clone()});
}

ObjectiveValue PopulationObjective::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  const int count = size();
  std::vector<ObjectiveValue> values(static_cast<size_t>(count));
  ForEachInParallel(count,
                    [&](int b) { values[b] = members_[b].objective->Evaluate(x, with_gradient); });
  ObjectiveValue out;
  for (const ObjectiveValue& v : values) {
    out.newton_iterations += v.newton_iterations;
    out.seconds = std::max(out.seconds, v.seconds);  // side by side: the slowest
    out.timing += v.timing;
  }
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
  for (int b = 0; b < count; ++b) {
    out.zeta += weights_[b] * values[b].zeta / members_[b].scale;
    out.psi += weights_[b] * values[b].psi / members_[b].scale;
  }
  if (with_gradient) {
    out.gradient = Eigen::VectorXd::Zero(x.size());
    for (int b = 0; b < count; ++b)
      out.gradient += (dF_dr[b] / members_[b].scale) * values[b].gradient;
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
  return members_.front().objective->LargestMove(dx);  // one design space for all
}

double PopulationObjective::BoxHalfWidthForMove(double move) const {
  return members_.front().objective->BoxHalfWidthForMove(move);
}

std::string PopulationObjective::Describe() const {
  std::string text =
      PopulationAggregateName(options_.aggregate) + " over " + std::to_string(size()) + " bodies (";
  for (int b = 0; b < size(); ++b) text += (b ? ", " : "") + members_[b].name;
  return text + ")";
}

}  // namespace ergo
