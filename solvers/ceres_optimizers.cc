#include "solvers/ceres_optimizers.h"

#include <cmath>
#include <utility>

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>
#include <glog/logging.h>

#include "solvers/design_scaling.h"
#include "solvers/run_monitor.h"

namespace ergo {
namespace {

// The objective on u, evaluated through the monitor (which may refuse: budget, interrupt;
// Ceres then sees a failed evaluation, backs off, and the callback ends the run).
class ScaledObjective : public ceres::FirstOrderFunction {
 public:
  ScaledObjective(Objective* objective, RunMonitor* monitor, Eigen::VectorXd origin,
                  DesignScaling scaling)
      : objective_(objective), monitor_(monitor), origin_(std::move(origin)), scaling_(scaling) {}

  // The same expression for x everywhere, so iterates match evaluated designs bit for bit.
  Eigen::VectorXd DesignAt(const double* u) const {
    return origin_ + scaling_.length_scale * Eigen::Map<const Eigen::VectorXd>(u, origin_.size());
  }

  bool Evaluate(const double* u, double* cost, double* gradient) const override {
    ObjectiveValue value;
    if (!monitor_->Evaluate(*objective_, DesignAt(u), gradient != nullptr, &value) || !value.ok)
      return false;
    *cost = value.phi / scaling_.value_scale;
    if (gradient) {
      Eigen::Map<Eigen::VectorXd>(gradient, origin_.size()) =
          value.gradient * (scaling_.length_scale / scaling_.value_scale);
    }
    return true;
  }

  int NumParameters() const override { return static_cast<int>(origin_.size()); }

 private:
  Objective* objective_;
  RunMonitor* monitor_;
  Eigen::VectorXd origin_;
  DesignScaling scaling_;
};

// Records Ceres' iterates in the history (with the values evaluated there) and stops the
// solver when the monitor says so.
class HistoryCallback : public ceres::IterationCallback {
 public:
  HistoryCallback(std::string name, const ScaledObjective* function, const Objective* objective,
                  RunMonitor* monitor, const double* u, Eigen::VectorXd x0)
      : name_(std::move(name)),
        function_(function),
        objective_(objective),
        monitor_(monitor),
        u_(u),
        previous_(std::move(x0)) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration > 0 && summary.step_is_successful) {
      const Eigen::VectorXd x = function_->DesignAt(u_);
      bool exact = false;
      const RunMonitor::Logged logged = monitor_->Lookup(x, &exact);
      // Ceres adopts the line search's evaluated point, so this does not happen; if it
      // did, the history would show the nearest evaluated design's values — say so.
      LOG_IF(WARNING, !exact) << name_ << " iteration " << summary.iteration
                              << ": the iterate is not among the evaluated designs; the "
                                 "history shows the nearest evaluated one";
      monitor_->AddIteration({summary.iteration, 0, 0, 0, logged.phi, logged.terms,
                              logged.gradient_norm, objective_->LargestMove(x - previous_),
                              EvaluationTiming()});
      previous_ = x;
    }
    return monitor_->ShouldStop() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  std::string name_;
  const ScaledObjective* function_;
  const Objective* objective_;
  RunMonitor* monitor_;
  const double* u_;
  Eigen::VectorXd previous_;
};

class CeresOptimizer : public Optimizer {
 public:
  CeresOptimizer(CeresDirection direction, CeresSettings settings)
      : direction_(direction), settings_(settings) {}

  std::string name() const override {
    return direction_ == CeresDirection::kLbfgs ? "ceres-lbfgs" : "ceres-ncg";
  }

  OptimizerResult Minimize(Objective& objective, const Eigen::VectorXd& x0, const Budget& budget,
                           const RunControl& control) override {
    RunMonitor monitor(name(), budget, control);
    ObjectiveValue value;
    if (!monitor.Evaluate(objective, x0, true, &value)) return monitor.Finish("no evaluation");
    if (!value.ok) return monitor.Finish("failed: x₀ could not be evaluated: " + value.message);
    monitor.AddIteration(
        {0, 0, 0, 0, value.phi, value.terms, value.gradient.norm(), 0, EvaluationTiming()});

    DesignScaling scaling;
    scaling.value_scale = std::abs(value.phi) > 0 ? std::abs(value.phi) : 1.0;
    scaling.length_scale = objective.LengthScale();
    auto* function = new ScaledObjective(&objective, &monitor, x0, scaling);
    ceres::GradientProblem problem(function);  // takes ownership of `function`
    Eigen::VectorXd u = Eigen::VectorXd::Zero(x0.size());
    HistoryCallback callback(name(), function, &objective, &monitor, u.data(), x0);

    ceres::GradientProblemSolver::Options options;
    if (direction_ == CeresDirection::kLbfgs) {
      options.line_search_direction_type = ceres::LBFGS;
      options.max_lbfgs_rank = settings_.max_lbfgs_rank;
      options.use_approximate_eigenvalue_bfgs_scaling = settings_.eigenvalue_scaling;
    } else {
      options.line_search_direction_type = ceres::NONLINEAR_CONJUGATE_GRADIENT;
      options.nonlinear_conjugate_gradient_type =
          settings_.polak_ribiere ? ceres::POLAK_RIBIERE : ceres::FLETCHER_REEVES;
    }
    // Every iteration costs at least one evaluation, so the evaluation budget bounds the
    // iterations; the monitor enforces it exactly.
    options.max_num_iterations = std::max(1, budget.max_evaluations);
    options.max_solver_time_in_seconds = budget.max_seconds > 0 ? budget.max_seconds : 1e9;
    // On the scaled problem: relative change of φ, relative φ change per mm, mm.
    options.function_tolerance = budget.function_tolerance;
    options.gradient_tolerance = budget.gradient_tolerance;
    options.parameter_tolerance = budget.parameter_tolerance;
    options.logging_type = ceres::SILENT;
    options.update_state_every_iteration = true;  // the callback reads the iterate
    options.callbacks.push_back(&callback);

    ceres::GradientProblemSolver::Summary summary;
    ceres::Solve(options, problem, u.data(), &summary);
    return monitor.Finish("ceres: " + summary.message);
  }

 private:
  CeresDirection direction_;
  CeresSettings settings_;
};

}  // namespace

std::unique_ptr<Optimizer> MakeCeresOptimizer(CeresDirection direction,
                                              const CeresSettings& settings) {
  return std::make_unique<CeresOptimizer>(direction, settings);
}

}  // namespace ergo
