#include "solvers/optimizer.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "solvers/ceres_optimizers.h"
#include "solvers/nlopt_optimizers.h"
#include "solvers/probe_descent.h"

namespace ergo {

std::string TimeBudgetReason(double max_seconds) {
  std::ostringstream out;
  out << "budget: " << max_seconds << " s wall";
  return out.str();
}

double OptimizerResult::ReductionPercent() const {
  if (!ok || !(std::abs(initial_phi) > 0)) return 0.0;
  return 100.0 * (1.0 - best_phi / initial_phi);
}

std::string OptimizerResult::BriefReport() const {
  std::ostringstream out;
  out << optimizer << ": ";
  if (!ok) {
    out << "no successful evaluation (" << stop_reason << ")";
    return out.str();
  }
  out << std::setprecision(6) << "φ " << initial_phi << " → " << best_phi << " ("
      << std::setprecision(3) << ReductionPercent() << " % lower), " << evaluations
      << " evaluations (" << failed_evaluations << " failed), " << newton_iterations
      << " Newton iterations, " << seconds << " s; " << stop_reason;
  return out.str();
}

std::vector<std::string> OptimizerResult::TermNames() const {
  std::vector<std::string> names;
  for (const ObjectiveTerm& term : best_terms) names.push_back(term.name);
  for (const IterationRecord& r : history)
    for (const ObjectiveTerm& term : r.terms)
      if (std::find(names.begin(), names.end(), term.name) == names.end())
        names.push_back(term.name);
  return names;
}

std::string OptimizerResult::FullReport() const {
  std::ostringstream out;
  out << BriefReport() << "\n";
  const std::vector<std::string> names = TermNames();
  out << "  iter  evals  newton     wall_s          phi";
  for (const std::string& name : names) out << std::setw(13) << name;
  out << "    |grad|      step_m\n";
  for (const IterationRecord& r : history) {
    out << std::setw(6) << r.iteration << std::setw(7) << r.evaluations << std::setw(8)
        << r.newton_iterations << std::setw(11) << std::setprecision(4) << r.seconds
        << std::setw(13) << std::setprecision(6) << r.phi;
    for (const std::string& name : names) out << std::setw(13) << TermValue(r.terms, name);
    out << std::setw(10) << std::setprecision(3) << r.gradient_norm << std::setw(12) << r.step
        << "\n";
  }
  return out.str();
}

std::vector<std::string> OptimizerNames() {
  return {"paper-ncg",   "ceres-lbfgs", "ceres-ncg",     "nlopt-mma",
          "nlopt-ccsaq", "nlopt-lbfgs", "nlopt-tnewton", "steepest"};
}

std::unique_ptr<Optimizer> MakeOptimizer(const std::string& name, const OptimizerOptions& options,
                                         std::string* error) {
  if (name == "paper-ncg") return MakeProbeDescent(ProbeDirection::kPolakRibiere, options.probes);
  if (name == "steepest") return MakeProbeDescent(ProbeDirection::kSteepest, options.probes);
  if (name == "ceres-lbfgs") return MakeCeresOptimizer(CeresDirection::kLbfgs, options.ceres);
  if (name == "ceres-ncg") {
    return MakeCeresOptimizer(CeresDirection::kNonlinearConjugateGradient, options.ceres);
  }
  if (name == "nlopt-mma") return MakeNloptOptimizer(NloptMethod::kMma, options.limits);
  if (name == "nlopt-ccsaq") return MakeNloptOptimizer(NloptMethod::kCcsaq, options.limits);
  if (name == "nlopt-lbfgs") return MakeNloptOptimizer(NloptMethod::kLbfgs, options.limits);
  if (name == "nlopt-tnewton") return MakeNloptOptimizer(NloptMethod::kTnewton, options.limits);
  if (error) {
    *error = "unknown optimiser \"" + name + "\"; known:";
    for (const std::string& known : OptimizerNames()) *error += " " + known;
  }
  return nullptr;
}

}  // namespace ergo
