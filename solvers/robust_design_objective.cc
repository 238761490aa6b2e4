#include "solvers/robust_design_objective.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include <glog/logging.h>

namespace ergo {

RobustDesignObjective::RobustDesignObjective(const DesignProblem& problem,
                                             const std::vector<Placement>& placements)
    : placements_(placements) {
  CHECK(!placements.empty());
  for (const Placement& placement : placements) {
    const bool centred = placement.shift.isZero() && placement.tilt.isZero();
    auto placed =
        std::make_unique<DesignProblem>(centred ? problem : PlacedProblem(problem, placement));
    // PlacedProblem places afresh at every evaluation; each placement here follows its own
    // path in the problem's mode (a followed path starts fresh), as the centred one does.
    placed->set_placement(problem.options().placement);
    problems_.push_back(std::move(placed));
  }
}

RobustDesignObjective::RobustDesignObjective(const RobustDesignObjective& other)
    : placements_(other.placements_) {
  for (const auto& problem : other.problems_)
    problems_.push_back(std::make_unique<DesignProblem>(*problem));
}

ObjectiveValue RobustDesignObjective::Evaluate(const Eigen::VectorXd& x, bool with_gradient) {
  const int count = placement_count();
  std::vector<DesignEvaluation> results(static_cast<size_t>(count));
  ForEachInParallel(count, [&](int p) { results[p] = problems_[p]->Evaluate(x, with_gradient); });

  ObjectiveValue out;
  for (const DesignEvaluation& r : results) {
    out.newton_iterations += r.equilibrium.iterations;
    // The placements ran side by side: the evaluation's wall time is the longest, its time
    // split the sum of theirs.
    out.seconds = std::max(out.seconds, r.timing.total_seconds);
    out.timing += r.timing;
  }
  for (int p = 0; p < count; ++p) {
    if (!results[p].ok) {
      out.ok = false;
      out.message = "placement " + placements_[p].name + ": " + results[p].message;
      return out;
    }
  }
  out.ok = true;
  out.message = "ok";
  if (with_gradient) out.gradient = Eigen::VectorXd::Zero(x.size());
  for (int p = 0; p < count; ++p) {
    const DesignEvaluation& r = results[p];
    out.phi += r.phi / count;
    AddScaledTerms(DesignTerms(r, problems_[p]->options().gamma), 1.0 / count, &out.terms);
    if (with_gradient) out.gradient += r.gradient / count;
  }
  return out;
}

std::unique_ptr<Objective> RobustDesignObjective::Clone() const {
  return std::make_unique<RobustDesignObjective>(*this);
}

double RobustDesignObjective::LargestMove(const Eigen::VectorXd& dx) const {
  const Eigen::VectorXd moves = problems_.front()->parameterization().VertexMoves(dx);
  return moves.size() == 0 ? 0.0 : moves.maxCoeff();
}

double RobustDesignObjective::BoxHalfWidthForMove(double move) const {
  return problems_.front()->parameterization().kind() == DesignParameterization::kPositions
             ? move / std::sqrt(3.0)
             : move;
}

std::string RobustDesignObjective::Describe() const {
  std::string names;
  for (const Placement& p : placements_) names += (names.empty() ? "" : ", ") + p.name;
  return "mean over " + std::to_string(placement_count()) + " placements (" + names + ")";
}

std::vector<Placement> RobustPlacements(const LayeredBody& body, int count, double shift,
                                        double tilt) {
  CHECK(count == 1 || count == 3 || count == 5);
  CHECK(tilt >= 0);
  std::vector<Placement> placements(1);
  placements[0].name = "centred";
  // PlacementChecks: ± along the first horizontal axis, then ± along the second.
  const std::vector<Placement> shifts = PlacementChecks(body, shift, 0, /*with_tilts=*/false);
  if (count == 5) {
    placements.insert(placements.end(), shifts.begin(), shifts.end());
  } else if (count == 3) {
    // ± along the body's longer horizontal extent (a foot's length, a seat's depth).
    const Vertices& rest = body.rest().vertices;
    const Eigen::RowVector3d extent = rest.colwise().maxCoeff() - rest.colwise().minCoeff();
    const double first = std::abs(extent.dot(shifts[0].shift.normalized().transpose()));
    const double second = std::abs(extent.dot(shifts[2].shift.normalized().transpose()));
    const int offset = first >= second ? 0 : 2;
    placements.push_back(shifts[offset]);
    placements.push_back(shifts[offset + 1]);
  }
  const std::vector<Placement> tilts = HeldTilts(body, tilt);
  placements.insert(placements.end(), tilts.begin(), tilts.end());
  return placements;
}

}  // namespace ergo
