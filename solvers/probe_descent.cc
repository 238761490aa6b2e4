#include "solvers/probe_descent.h"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "solvers/probe_line_search.h"
#include "solvers/run_monitor.h"

namespace ergo {
namespace {

std::string Format(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

class ProbeDescent : public Optimizer {
 public:
  ProbeDescent(ProbeDirection direction, ProbeOptions options)
      : direction_(direction), options_(std::move(options)) {}

  std::string name() const override {
    return direction_ == ProbeDirection::kPolakRibiere ? "paper-ncg" : "steepest";
  }

  OptimizerResult Minimize(Objective& objective, const Eigen::VectorXd& x0, const Budget& budget,
                           const RunControl& control) override {
    RunMonitor monitor(name(), budget, control);
    ProbeLineSearch line_search(options_);
    ObjectiveValue value;
    if (!monitor.Evaluate(objective, x0, true, &value)) return monitor.Finish("no evaluation");
    if (!value.ok) return monitor.Finish("failed: x₀ could not be evaluated: " + value.message);
    monitor.AddIteration(
        {0, 0, 0, 0, value.phi, value.terms, value.gradient.norm(), 0, EvaluationTiming()});

    const double value_scale = std::abs(value.phi) > 0 ? std::abs(value.phi) : 1.0;
    const double length_scale = objective.LengthScale();
    const int n = objective.NumParameters();
    const int restart_every = options_.restart_every > 0 ? options_.restart_every : n;

    std::unique_ptr<Objective> owned;  // the clone holding the current design's equilibrium
    Objective* current = &objective;
    Eigen::VectorXd x = x0, g = value.gradient, g_previous, d_previous;
    double phi = value.phi;
    bool restart = true;
    int since_restart = 0;
    std::string reason;
    int iteration = 0;  // accepted iterates
    for (;;) {
      if (monitor.ShouldStop()) break;
      const double scaled_gradient = g.lpNorm<Eigen::Infinity>() * length_scale / value_scale;
      if (scaled_gradient <= budget.gradient_tolerance) {
        reason = "gradient tolerance: scaled ‖∇φ‖∞ = " + Format(scaled_gradient);
        break;
      }
      // Direction: PR+ conjugate gradient, or −∇φ (steepest, restarts).
      Eigen::VectorXd d = -g;
      bool steepest = true;
      if (direction_ == ProbeDirection::kPolakRibiere && !restart &&
          since_restart < restart_every) {
        const double beta = std::max(0.0, g.dot(g - g_previous) / g_previous.squaredNorm());
        const Eigen::VectorXd conjugate = -g + beta * d_previous;
        if (beta > 0 && g.dot(conjugate) < 0) {
          d = conjugate;
          steepest = false;
        }
      }
      since_restart = steepest ? 1 : since_restart + 1;
      if (!(objective.LargestMove(d) > 0)) {
        reason = "gradient tolerance: ∇φ moves no vertex";
        break;
      }

      ProbeOutcome outcome = line_search.Search(*current, x, phi, d, &monitor);
      if (outcome.accepted < 0) {
        if (monitor.ShouldStop()) break;  // the budget ran out among the probes
        if (!steepest) {                  // retry once along −∇φ before giving up
          restart = true;
          continue;
        }
        reason = "stalled: no probe along −∇φ lowered φ (" + std::to_string(outcome.failed) +
                 " of " + std::to_string(outcome.evaluated) + " probes failed)";
        break;
      }
      if (!options_.gradient_at_probes) {
        ObjectiveValue with_gradient;
        if (!monitor.Evaluate(*outcome.objective, outcome.x, true, &with_gradient)) break;
        if (!with_gradient.ok) {
          reason = "failed: re-evaluating the accepted probe with ∇φ: " + with_gradient.message;
          break;
        }
        outcome.value.gradient = with_gradient.gradient;
      }
      const double step = objective.LargestMove(outcome.x - x);
      const double decrease = (phi - outcome.value.phi) / std::abs(phi);
      g_previous = std::move(g);
      d_previous = std::move(d);
      g = outcome.value.gradient;
      x = std::move(outcome.x);
      phi = outcome.value.phi;
      owned = std::move(outcome.objective);
      current = owned.get();
      restart = false;
      monitor.AddIteration(
          {++iteration, 0, 0, 0, phi, outcome.value.terms, g.norm(), step, EvaluationTiming()});
      if (decrease < budget.function_tolerance) {
        reason = "function tolerance: φ fell by " + Format(100 * decrease) + " %";
        break;
      }
      if (step <= budget.parameter_tolerance * 1e-3) {
        reason = "parameter tolerance: the step moved no vertex more than " + Format(step) + " m";
        break;
      }
    }
    return monitor.Finish(reason);
  }

 private:
  ProbeDirection direction_;
  ProbeOptions options_;
};

}  // namespace

std::unique_ptr<Optimizer> MakeProbeDescent(ProbeDirection direction, const ProbeOptions& options) {
  return std::make_unique<ProbeDescent>(direction, options);
}

}  // namespace ergo
