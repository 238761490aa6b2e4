#include "tools/ergo_population/population_report.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "ergo/design/evaluation_timing.h"
#include "ergo/mesh/atomic_file.h"

namespace ergo {
namespace {

double Worst(const PopulationSummary& s, bool mean_design) {
  double worst = INFINITY;
  for (const BodyOutcome& b : s.bodies)
    worst = std::min(worst, mean_design ? b.MeanDesignReductionPercent() : b.ReductionPercent());
  return worst;
}

Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

}  // namespace

Json PopulationSummaryJson(const PopulationSummary& s) {
  Json j = Json::object();
  j["population"] = s.population;
  j["description"] = s.description;
  j["objective"] = s.objective;
  j["objective_options"] = s.objective_options;
  j["optimizer"] = s.optimizer;
  j["ranks"] = s.ranks;
  j["threads_per_rank"] = s.threads;
  j["robust_placements"] = s.robust_placements;
  j["initial_score"] = Number(s.initial_score);
  j["optimized_score"] = Number(s.optimized_score);
  j["reduction_percent"] = Number(100.0 * (1.0 - s.optimized_score / s.initial_score));
  j["worst_body_reduction_percent"] = Number(Worst(s, false));
  if (s.mean_design) {
    Json mean = Json::object();
    mean["optimized_score"] = Number(s.mean_design_score);
    mean["reduction_percent"] = Number(100.0 * (1.0 - s.mean_design_score / s.initial_score));
    mean["worst_body_reduction_percent"] = Number(Worst(s, true));
    j["mean_body_design"] = mean;
  }
  Json bodies = Json::array();
  for (const BodyOutcome& b : s.bodies) {
    Json body = Json::object();
    body["name"] = b.name;
    body["weight"] = b.weight;
    Json flags = Json::object();
    for (const auto& [name, value] : b.flags) flags[name] = value;
    body["flags"] = flags;
    body["initial_score"] = Number(b.initial_score);
    body["optimized_score"] = Number(b.optimized_score);
    body["reduction_percent"] = Number(b.ReductionPercent());
    body["initial_peak_pressure"] = Number(b.initial_peak);
    body["optimized_peak_pressure"] = Number(b.optimized_peak);
    if (s.mean_design) {
      body["mean_body_design_score"] = Number(b.mean_design_score);
      body["mean_body_design_reduction_percent"] = Number(b.MeanDesignReductionPercent());
      body["mean_body_design_peak_pressure"] = Number(b.mean_design_peak);
    }
    bodies.push_back(body);
  }
  j["bodies"] = bodies;
  j["evaluations"] = s.result.evaluations;
  j["failed_evaluations"] = s.result.failed_evaluations;
  j["newton_iterations"] = s.result.newton_iterations;
  j["stop_reason"] = s.result.stop_reason;
  j["wall_seconds"] = s.wall_seconds;
  j["reduction_bytes_per_evaluation"] = s.bytes_per_evaluation;
  j["interrupted"] = s.interrupted;
  j["time_split"] = TimingJson(s.result.timing);
  return j;
}

std::string PopulationSummaryMarkdown(const PopulationSummary& s) {
  std::ostringstream md;
  md << std::fixed << std::setprecision(1);
  md << "# Population design: " << s.description << "\n\n";
  md << "Population `" << s.population << "`, " << s.bodies.size() << " bodies; objective "
     << s.objective << " of each body's score placed afresh (mean over " << s.robust_placements
     << " placement(s)), relative to its score on the initial design; optimiser " << s.optimizer
     << "; " << s.ranks << " rank(s) × " << s.threads << " thread(s).\n\n";
  md << "| | population objective | reduction | worst body's reduction |\n|---|---|---|---|\n";
  md << std::setprecision(4) << "| initial design | " << s.initial_score << " | | |\n";
  md << "| population design | " << s.optimized_score << " | " << std::setprecision(1)
     << 100.0 * (1.0 - s.optimized_score / s.initial_score) << " % | " << Worst(s, false)
     << " % |\n";
  if (s.mean_design)
    md << std::setprecision(4) << "| mean body's design | " << s.mean_design_score << " | "
       << std::setprecision(1) << 100.0 * (1.0 - s.mean_design_score / s.initial_score) << " % | "
       << Worst(s, true) << " % |\n";
  md << "\n| body | weight | reduction (population design) | peak kPa before → after |";
  if (s.mean_design) md << " reduction (mean body's design) |";
  md << "\n|---|---|---|---|" << (s.mean_design ? "---|" : "") << "\n";
  for (const BodyOutcome& b : s.bodies) {
    md << "| " << b.name << " | " << std::setprecision(3) << b.weight << " | "
       << std::setprecision(1) << b.ReductionPercent() << " % | " << b.initial_peak / 1e3 << " → "
       << b.optimized_peak / 1e3 << " |";
    if (s.mean_design) md << " " << b.MeanDesignReductionPercent() << " % |";
    md << "\n";
  }
  md << "\n"
     << s.result.evaluations << " evaluations (" << s.result.failed_evaluations << " failed), "
     << s.result.newton_iterations << " Newton iterations, " << std::setprecision(0)
     << s.wall_seconds << " s wall; stop: " << s.result.stop_reason
     << (s.interrupted ? " (interrupted)" : "") << ".\n";
  if (s.ranks > 1)
    md << "Reductions: " << s.bytes_per_evaluation << " bytes per rank and evaluation.\n";
  return md.str();
}

void WriteBodiesCsv(const std::string& path, const PopulationSummary& s) {
  WriteFileAtomically(path, [&](std::ostream& csv) {
    csv << std::setprecision(17);
    csv << "name,weight,initial_score,optimized_score,reduction_percent,initial_peak_pressure_Pa,"
           "optimized_peak_pressure_Pa,mean_body_design_score,"
           "mean_body_design_reduction_percent\n";
    for (const BodyOutcome& b : s.bodies) {
      csv << b.name << "," << b.weight << "," << b.initial_score << "," << b.optimized_score << ","
          << b.ReductionPercent() << "," << b.initial_peak << "," << b.optimized_peak << ",";
      if (s.mean_design)
        csv << b.mean_design_score << "," << b.MeanDesignReductionPercent();
      else
        csv << ",";
      csv << "\n";
    }
  });
}

}  // namespace ergo
