#include "solvers/nlopt_optimizers.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include <glog/logging.h>
#include <nlopt.hpp>

#include "solvers/design_scaling.h"
#include "solvers/run_monitor.h"

namespace ergo {
namespace {

const char* ResultName(nlopt::result result) {
  switch (result) {
    case nlopt::FAILURE:
      return "failure";
    case nlopt::INVALID_ARGS:
      return "invalid arguments";
    case nlopt::OUT_OF_MEMORY:
      return "out of memory";
    case nlopt::ROUNDOFF_LIMITED:
      return "roundoff-limited";
    case nlopt::FORCED_STOP:
      return "forced stop";
    case nlopt::SUCCESS:
      return "success";
    case nlopt::STOPVAL_REACHED:
      return "stopval reached";
    case nlopt::FTOL_REACHED:
      return "function tolerance reached";
    case nlopt::XTOL_REACHED:
      return "parameter tolerance reached";
    case nlopt::MAXEVAL_REACHED:
      return "round evaluations reached";
    case nlopt::MAXTIME_REACHED:
      return "time reached";
    default:
      return "unknown result";
  }
}

// Shared by the rounds: evaluates through the monitor, tracks the best design in u (so a
// round restarts at exactly the evaluated vector) and writes the history at each new best.
struct Run {
  Objective* objective = nullptr;
  RunMonitor* monitor = nullptr;
  nlopt::opt* opt = nullptr;  // the round's optimiser (for force_stop)
  Eigen::VectorXd origin;
  DesignScaling scaling;
  Eigen::VectorXd lower, upper;  // the total move box, u
  double gradient_tolerance = 0;
  Eigen::VectorXd best_u, previous_x;
  double best_phi = 0;
  int iteration = 0;
  bool gradient_converged = false;

  Eigen::VectorXd DesignAt(const double* u) const {
    return origin + scaling.length_scale * Eigen::Map<const Eigen::VectorXd>(u, origin.size());
  }

  // ‖∇f‖∞ over the directions the total box leaves open.
  double ProjectedGradient(const Eigen::VectorXd& u, const Eigen::VectorXd& g) const {
    double norm = 0;
    for (Eigen::Index i = 0; i < g.size(); ++i) {
      if ((u[i] <= lower[i] && g[i] > 0) || (u[i] >= upper[i] && g[i] < 0)) continue;
      norm = std::max(norm, std::abs(g[i]));
    }
    return norm;
  }

  double Evaluate(const double* u, double* gradient) {
    const Eigen::Index n = origin.size();
    const Eigen::VectorXd x = DesignAt(u);
    ObjectiveValue value;
    const bool admitted = monitor->Evaluate(*objective, x, gradient != nullptr, &value);
    if (!admitted || !value.ok) {
      if (!admitted) opt->force_stop();
      if (gradient) std::fill(gradient, gradient + n, 0.0);
      // +∞: MMA/CCSAQ treat it as "not conservative" and shrink the step.
      return std::numeric_limits<double>::infinity();
    }
    const double f = value.phi / scaling.value_scale;
    Eigen::VectorXd g;
    if (gradient) {
      g = value.gradient * (scaling.length_scale / scaling.value_scale);
      Eigen::Map<Eigen::VectorXd>(gradient, n) = g;
    }
    if (value.phi < best_phi) {
      best_phi = value.phi;
      best_u = Eigen::Map<const Eigen::VectorXd>(u, n);
      monitor->AddIteration({++iteration, 0, 0, 0, value.phi, value.terms,
                             gradient ? value.gradient.norm() : -1.0,
                             objective->LargestMove(x - previous_x), EvaluationTiming()});
      previous_x = x;
      if (gradient && ProjectedGradient(best_u, g) <= gradient_tolerance) {
        gradient_converged = true;
        opt->force_stop();
      }
      if (monitor->stopped()) opt->force_stop();  // the progress callback said stop
    }
    return f;
  }
};

double NloptCallback(unsigned n, const double* u, double* gradient, void* data) {
  return static_cast<Run*>(data)->Evaluate(u, gradient);
}

nlopt::algorithm Algorithm(NloptMethod method) {
  switch (method) {
    case NloptMethod::kMma:
      return nlopt::LD_MMA;
    case NloptMethod::kCcsaq:
      return nlopt::LD_CCSAQ;
    case NloptMethod::kLbfgs:
      return nlopt::LD_LBFGS;
    case NloptMethod::kTnewton:
      return nlopt::LD_TNEWTON_PRECOND_RESTART;
  }
  return nlopt::LD_LBFGS;
}

class NloptOptimizer : public Optimizer {
 public:
  NloptOptimizer(NloptMethod method, MoveLimits limits) : method_(method), limits_(limits) {
    CHECK(limits_.total > 0) << "the total move cap must be positive";
    CHECK(limits_.per_round >= 0);
    CHECK(limits_.round_evaluations > 0);
  }

  std::string name() const override {
    switch (method_) {
      case NloptMethod::kMma:
        return "nlopt-mma";
      case NloptMethod::kCcsaq:
        return "nlopt-ccsaq";
      case NloptMethod::kLbfgs:
        return "nlopt-lbfgs";
      case NloptMethod::kTnewton:
        return "nlopt-tnewton";
    }
    return "nlopt";
  }

  OptimizerResult Minimize(Objective& objective, const Eigen::VectorXd& x0, const Budget& budget,
                           const RunControl& control) override {
    RunMonitor monitor(name(), budget, control);
    ObjectiveValue value;
    if (!monitor.Evaluate(objective, x0, true, &value)) return monitor.Finish("no evaluation");
    if (!value.ok) return monitor.Finish("failed: x₀ could not be evaluated: " + value.message);
    monitor.AddIteration(
        {0, 0, 0, 0, value.phi, value.terms, value.gradient.norm(), 0, EvaluationTiming()});

    const Eigen::Index n = x0.size();
    const double length = objective.LengthScale();
    Run run;
    run.objective = &objective;
    run.monitor = &monitor;
    run.origin = x0;
    run.scaling.value_scale = std::abs(value.phi) > 0 ? std::abs(value.phi) : 1.0;
    run.scaling.length_scale = length;
    const double total = objective.BoxHalfWidthForMove(limits_.total) / length;
    const double per_round = limits_.per_round > 0
                                 ? objective.BoxHalfWidthForMove(limits_.per_round) / length
                                 : std::numeric_limits<double>::infinity();
    run.lower = Eigen::VectorXd::Constant(n, -total);
    run.upper = Eigen::VectorXd::Constant(n, total);
    run.gradient_tolerance = budget.gradient_tolerance;
    run.best_u = Eigen::VectorXd::Zero(n);
    run.previous_x = x0;
    run.best_phi = value.phi;
    if (run.ProjectedGradient(run.best_u, value.gradient * (length / run.scaling.value_scale)) <=
        budget.gradient_tolerance) {
      return monitor.Finish("gradient tolerance at x₀");
    }

    const nlopt::algorithm algorithm = Algorithm(method_);
    std::string reason;
    for (int round = 0;; ++round) {
      if (monitor.ShouldStop()) break;
      const Eigen::VectorXd round_lower =
          run.lower.array().max(run.best_u.array() - per_round).matrix();
      const Eigen::VectorXd round_upper =
          run.upper.array().min(run.best_u.array() + per_round).matrix();
      nlopt::opt opt(algorithm, static_cast<unsigned>(n));
      run.opt = &opt;
      opt.set_min_objective(NloptCallback, &run);
      opt.set_lower_bounds(std::vector<double>(round_lower.data(), round_lower.data() + n));
      opt.set_upper_bounds(std::vector<double>(round_upper.data(), round_upper.data() + n));
      opt.set_ftol_rel(budget.function_tolerance);
      opt.set_xtol_abs(objective.BoxHalfWidthForMove(budget.parameter_tolerance * 1e-3) / length);
      const long remaining = monitor.RemainingEvaluations();
      const long round_budget =
          limits_.per_round > 0 ? std::min<long>(limits_.round_evaluations, remaining) : remaining;
      // +1: each round starts at the best design, answered from memory (not evaluated).
      opt.set_maxeval(static_cast<int>(round_budget + 1));
      if (budget.max_seconds > 0)
        opt.set_maxtime(std::max(1e-3, budget.max_seconds - monitor.Seconds()));

      std::vector<double> u(run.best_u.data(), run.best_u.data() + n);
      const double phi_before = run.best_phi;
      nlopt::result result = nlopt::FAILURE;
      std::string error;
      double f = 0;
      try {
        result = opt.optimize(u, f);
      } catch (const nlopt::forced_stop&) {
        result = nlopt::FORCED_STOP;
      } catch (const nlopt::roundoff_limited&) {
        result = nlopt::ROUNDOFF_LIMITED;
      } catch (const std::exception& e) {
        result = opt.last_optimize_result();
        error = e.what();
      }
      run.opt = nullptr;
      if (run.gradient_converged) {
        reason = "gradient tolerance";
        break;
      }
      if (monitor.ShouldStop()) break;
      const bool improved = run.best_phi < phi_before;
      const std::string what =
          std::string("nlopt: ") + ResultName(result) + (error.empty() ? "" : " (" + error + ")");
      if (result < 0) {  // failure, roundoff-limited, ...: another round only after progress
        if (!improved) {
          reason = what;
          break;
        }
        continue;
      }
      if (result == nlopt::MAXEVAL_REACHED) {
        if (!improved) {
          reason = "stalled: a round of " + std::to_string(round_budget) +
                   " evaluations did not lower φ";
          break;
        }
        continue;
      }
      if (result == nlopt::MAXTIME_REACHED) {
        reason = TimeBudgetReason(budget.max_seconds);
        break;
      }
      // Converged inside the round's box: final, unless the best touches a move limit that
      // the next round would relax.
      bool on_round_face = false;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double tolerance = 1e-12 * std::max(1.0, std::abs(run.best_u[i]));
        on_round_face |=
            (round_lower[i] > run.lower[i] && run.best_u[i] <= round_lower[i] + tolerance) ||
            (round_upper[i] < run.upper[i] && run.best_u[i] >= round_upper[i] - tolerance);
      }
      if (!on_round_face || !improved) {
        reason = what;
        break;
      }
    }
    return monitor.Finish(reason);
  }

 private:
  NloptMethod method_;
  MoveLimits limits_;
};

}  // namespace

std::unique_ptr<Optimizer> MakeNloptOptimizer(NloptMethod method, const MoveLimits& limits) {
  return std::make_unique<NloptOptimizer>(method, limits);
}

}  // namespace ergo
