// The summary of an ergo_optimize run (summary.json and summary.md): the paper's Table 1
// columns with the body placed afresh on the kept design as the headline, the figures on the
// path the optimiser followed beside them, the placement checks (the body landing a few
// millimetres off or tilted), what the person feels (the skin's side of ζ, its contact area,
// the peak pressure and its relief, with the clinical reading for a shoe) and the run's
// counts with their time split (time_split: ergo/design/evaluation_timing.h). SI units in the
// JSON; the markdown shows kPa, mm and cm².
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "ergo/design/placement_checks.h"
#include "ergo/mesh/json.h"
#include "problems/scenario.h"
#include "solvers/optimizer.h"
#include "tools/common/run_outputs.h"

namespace ergo {

// One placement check: the initial and the kept design scored with the body placed there.
struct PlacementOutcome {
  Placement placement;
  bool ok = false;
  std::string message;  // why not ok
  double initial_score = 0, score = 0;
  double ReductionPercent() const { return 100.0 * (1.0 - score / initial_score); }
};

struct RunSummary {
  const Scenario* scenario = nullptr;
  std::string optimizer;
  std::string placement;      // how evaluations were placed: fresh, anchored, followed
  int robust_placements = 1;  // placements averaged by the objective
  // Where the optimiser started: "initial" (x₀) or a baseline's design, and the objective's
  // value there (NaN for x₀, whose scores are initial_score).
  std::string start = "initial";
  double start_score = std::numeric_limits<double>::quiet_NaN();
  DesignReport initial;    // x₀, placed afresh
  DesignReport optimized;  // the kept design, placed afresh: the headline
  DesignReport followed;   // the kept design on the optimiser's own path (may not be ok)
  // The optimiser's own value of the kept design (its path), known even where the path's
  // report is not (after a resume): summary's followed_score.
  double followed_phi = std::numeric_limits<double>::quiet_NaN();
  std::vector<PlacementOutcome> checks;
  std::vector<double> candidate_phi;        // the optimiser's values of the checked designs
  std::vector<double> candidate_fresh_phi;  // the same designs placed afresh
  int kept_candidate = 0;
  std::string post_smoothing;  // one line when post-smoothing was tried
  // Non-empty when the body placed afresh on the designed support found no equilibrium and
  // the initial design is reported in its place: why (summary.json's kept_design_failure).
  std::string kept_design_failure;
  OptimizerResult result;  // counts, stop reason (its history is written separately)
  double gamma = 0, wall_seconds = 0;
  bool interrupted = false;
};

Json SummaryJson(const RunSummary& summary);
std::string SummaryMarkdown(const RunSummary& summary);

}  // namespace ergo
