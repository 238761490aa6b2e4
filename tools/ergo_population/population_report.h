// What ergo_population writes about a run: summary.json (optimized_score, reduction_percent,
// bodies: each body's name, weight, flags, fresh scores before and after, reduction_percent
// and peak skin pressures; the mean-body design's scores on every body beside them),
// summary.md (the same as tables) and bodies.csv (one row per body). Scores are each body's
// objective placed afresh (the mean over the robust placements), so that a body's
// reduction is what that person gets on the part.
#pragma once

#include <string>
#include <vector>

#include "ergo/mesh/json.h"
#include "problems/population.h"
#include "solvers/optimizer.h"

namespace ergo {

struct BodyOutcome {
  std::string name;
  double weight = 1;  // normalised
  FlagValues flags;
  double initial_score = 0, optimized_score = 0;           // placed afresh
  double initial_peak = 0, optimized_peak = 0;             // skin, Pa, centred placement
  double mean_design_score = NAN, mean_design_peak = NAN;  // the mean body's design
  double ReductionPercent() const { return 100.0 * (1.0 - optimized_score / initial_score); }
  double MeanDesignReductionPercent() const {
    return 100.0 * (1.0 - mean_design_score / initial_score);
  }
};

struct PopulationSummary {
  std::string population;  // the file
  std::string description;
  std::string objective;  // mean, meanstd, worst, cvar
  Json objective_options = Json::object();
  std::string optimizer;
  int ranks = 1, threads = 1, robust_placements = 1;
  double initial_score = 0, optimized_score = 0;  // the population objective, afresh
  bool mean_design = false;                       // the mean-body comparison was run
  double mean_design_score = NAN;                 // its design under the population objective
  std::vector<BodyOutcome> bodies;
  OptimizerResult result;
  double wall_seconds = 0;
  long long bytes_per_evaluation = 0;  // reduction payload per rank and evaluation (MPI)
  bool interrupted = false;
};

Json PopulationSummaryJson(const PopulationSummary& summary);
std::string PopulationSummaryMarkdown(const PopulationSummary& summary);
void WriteBodiesCsv(const std::string& path, const PopulationSummary& summary);

}  // namespace ergo
