#include "solvers/fresh_score_objective.h"

#include <cmath>

namespace ergo {
namespace {

DesignProblem PlacedAfresh(const DesignProblem& problem) {
  DesignProblem fresh(problem);
  fresh.set_placement(DesignPlacement::kFresh);
  fresh.ClearWarmStarts();
  return fresh;
}

}  // namespace

FreshScoreObjective::FreshScoreObjective(const DesignProblem& problem,
                                         std::vector<Placement> placements,
                                         const std::atomic<bool>* stop)
    : design_(PlacedAfresh(problem)), placements_(std::move(placements)), stop_(stop) {}

ObjectiveValue FreshScoreObjective::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  ObjectiveValue out;
  if (with_gradient) {
    out.message = "a fresh score has no gradient";
    return out;
  }
  out.phi = MeanPlacedPhi(design_.problem(), x, placements_, stop_, &out.timing);
  out.seconds = out.timing.total_seconds;
  out.newton_iterations = static_cast<int>(out.timing.newton_iterations);
  out.ok = std::isfinite(out.phi);
  out.message = out.ok ? "ok"
                       : "the body placed afresh did not reach equilibrium at every one of " +
                             std::to_string(placements_.size()) + " placements";
  if (!out.ok) out.phi = 0;
  if (out.ok) out.terms = {{"fresh_phi", 1, out.phi}};
  return out;
}

std::unique_ptr<Objective> FreshScoreObjective::Clone() const {
  return std::make_unique<FreshScoreObjective>(design_.problem(), placements_, stop_);
}

std::string FreshScoreObjective::Describe() const {
  return "placed afresh at " + std::to_string(placements_.size()) +
         " placements: " + design_.Describe();
}

}  // namespace ergo
