#include "tools/ergo_optimize/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "ergo/design/equilibrium_report.h"
#include "ergo/design/evaluation_timing.h"
#include "ergo/ergonomics/plate_reading.h"

namespace ergo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// In-shoe offloading is judged by a peak reduction above 30 % or a peak below 200 kPa (Bus et
// al. 2011; IWGDF guidance).
constexpr double kOffloadingRelief = 30, kOffloadingPeak = 2e5;

std::string Format(const char* format, double value) {
  if (!std::isfinite(value)) return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

double Reduction(double initial, double value) { return 100.0 * (1.0 - value / initial); }

// A value of a report, NaN where the report's equilibrium did not converge.
double Of(const DesignReport& report, double value) { return report.evaluation.ok ? value : kNaN; }

Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(); }

Json Pose(const DesignReport& report) {
  if (!report.evaluation.ok) return Json();
  const BodyState& state = report.evaluation.equilibrium.state;
  Json pose = Json::array();
  for (int k = 0; k < 3; ++k) pose.push_back(state.centre[k]);
  const Eigen::AngleAxisd angle(state.rotation);
  for (int k = 0; k < 3; ++k) pose.push_back(angle.angle() * angle.axis()[k]);
  return pose;
}

Json ThreeWay(double initial, double followed, double fresh) {
  Json out = Json::object();
  out["initial"] = Number(initial);
  out["followed"] = Number(followed);
  out["fresh"] = Number(fresh);
  return out;
}

bool IsShoe(const RunSummary& s) { return s.scenario->name == "shoe"; }

// The criterion's thresholds are sensor readings (in-shoe systems: Pedar's 99 sensels over an
// insole are about 2 cm² each), so it is read on the peak a 5 mm plate reads where there is one
// (the load seen along y), and on ergo's per-vertex peak otherwise.
struct OffloadingReading {
  bool on_plate = false;                    // else ergo's per-vertex peak
  double initial = kNaN, optimized = kNaN;  // Pa
  const char* name() const { return on_plate ? "5 mm plate" : "skin vertex"; }
  double relief() const { return Reduction(initial, optimized); }
  bool met() const { return relief() > kOffloadingRelief || optimized < kOffloadingPeak; }
};

OffloadingReading ReadOffloading(const RunSummary& s) {
  if (std::isfinite(s.initial.plate_peak_pressure) && s.initial.plate_peak_pressure > 0)
    return {true, s.initial.plate_peak_pressure, s.optimized.plate_peak_pressure};
  return {false, s.initial.peak_pressure, s.optimized.peak_pressure};
}

// The centre of pressure's fraction of the length from the regions' start (the heel).
double CentreFraction(const RunSummary& s, const CentreOfPressure& c) {
  return s.scenario->regions.from_min_z ? c.z_fraction : 1 - c.z_fraction;
}

double WorstCheckReduction(const RunSummary& s) {
  double worst = std::numeric_limits<double>::infinity();
  for (const PlacementOutcome& c : s.checks)
    worst = std::min(worst, c.ok ? c.ReductionPercent() : -std::numeric_limits<double>::infinity());
  return s.checks.empty() ? kNaN : worst;
}

}  // namespace

Json SummaryJson(const RunSummary& s) {
  const Scenario& scenario = *s.scenario;
  const DesignEvaluation& initial = s.initial.evaluation;
  const DesignEvaluation& fresh = s.optimized.evaluation;
  const DesignEvaluation& followed = s.followed.evaluation;
  const double phi0 = initial.phi;
  Json j = Json::object();
  j["scenario"] = scenario.name;
  j["description"] = scenario.description;
  j["optimizer"] = s.optimizer;
  j["placement"] = s.placement;
  j["robust_placements"] = s.robust_placements;
  j["start"] = s.start;
  j["start_score"] = Number(s.start_score);
  // The headline: the body placed afresh on the kept design.
  j["initial_score"] = phi0;
  j["optimized_score"] = Number(Of(s.optimized, fresh.phi));
  j["reduction_percent"] = Number(Of(s.optimized, Reduction(phi0, fresh.phi)));
  j["fresh_placement_converged"] = fresh.ok;
  j["kept_design_failure"] = s.kept_design_failure.empty() ? Json() : Json(s.kept_design_failure);
  j["followed_score"] = Number(s.followed_phi);
  j["followed_reduction_percent"] = Number(Reduction(phi0, s.followed_phi));
  j["initial_zeta"] = initial.zeta;
  j["optimized_zeta"] = Number(Of(s.optimized, fresh.zeta));
  j["followed_zeta"] = Number(Of(s.followed, followed.zeta));
  // What the person feels: the skin's side of ζ, its contact area, the peak pressure.
  j["skin_zeta"] = ThreeWay(initial.zeta_human, Of(s.followed, followed.zeta_human),
                            Of(s.optimized, fresh.zeta_human));
  j["support_zeta"] = ThreeWay(initial.zeta_support, Of(s.followed, followed.zeta_support),
                               Of(s.optimized, fresh.zeta_support));
  j["initial_skin_zeta"] = initial.zeta_human;
  j["optimized_skin_zeta"] = Number(Of(s.optimized, fresh.zeta_human));
  j["skin_zeta_reduction_percent"] =
      Number(Of(s.optimized, Reduction(initial.zeta_human, fresh.zeta_human)));
  j["skin_contact_area_m2"] =
      ThreeWay(s.initial.skin_contact_area, Of(s.followed, s.followed.skin_contact_area),
               Of(s.optimized, s.optimized.skin_contact_area));
  // Where the skin's contact force acts (a pressure plate's centre of pressure), and as a
  // fraction of the body's rest extent along z (the shoe: of the foot's length from the heel,
  // whichever end of z the heel is at).
  auto centre = [&](const DesignReport& report) {
    const CentreOfPressure& c = report.centre_of_pressure;
    if (!(c.normal_force > 0)) return Json();
    Json out = Json::object();
    out["point_m"] = Json::array({c.point.x(), c.point.y(), c.point.z()});
    out["z_fraction"] = CentreFraction(s, c);
    return out;
  };
  Json centres = Json::object();
  centres["initial"] = centre(s.initial);
  centres["optimized"] = s.optimized.evaluation.ok ? centre(s.optimized) : Json();
  j["centre_of_pressure"] = centres;
  // The load's split along the length as a pressure plate's masks read it (lengthwise_shares.h).
  const LengthRegions& regions = scenario.regions;
  if (!regions.names.empty()) {
    auto shares = [&](const DesignReport& report) {
      const std::vector<double>& values = report.region_shares;
      if (values.empty()) return Json();
      Json out = Json::object();
      for (size_t k = 0; k < values.size(); ++k) out[regions.names[k]] = values[k];
      return out;
    };
    Json split = Json::object();
    split["ends"] = Json::array();
    for (double end : regions.ends) split["ends"].push_back(end);
    split["initial"] = shares(s.initial);
    split["optimized"] = shares(s.optimized);
    j["region_shares"] = split;
  }
  // How hard each design's equilibrium squeezes the tissue: a peak carried through tets past the
  // material's inversion threshold is the law's extension, not tissue (tissue_compression.h).
  Json compression = Json::object();
  compression["initial"] = TissueCompressionJson(s.initial.compression);
  compression["optimized"] =
      s.optimized.evaluation.ok ? TissueCompressionJson(s.optimized.compression) : Json();
  j["tissue_compression"] = compression;
  j["initial_peak_pressure_Pa"] = s.initial.peak_pressure;
  j["fresh_peak_pressure_Pa"] = Number(Of(s.optimized, s.optimized.peak_pressure));
  j["optimized_peak_pressure_Pa"] = Number(Of(s.optimized, s.optimized.peak_pressure));
  j["followed_peak_pressure_Pa"] = Number(Of(s.followed, s.followed.peak_pressure));
  // What a 5 mm pressure plate under the skin would read at its largest cell (plate_reading.h):
  // the figure to compare with plate measurements, and one that does not grow as the mesh refines.
  j["initial_plate_peak_pressure_Pa"] = Number(s.initial.plate_peak_pressure);
  j["followed_plate_peak_pressure_Pa"] = Number(Of(s.followed, s.followed.plate_peak_pressure));
  j["plate_pitch_m"] = PlatePeakOptions().pitch;
  j["fresh_plate_peak_pressure_Pa"] = Number(Of(s.optimized, s.optimized.plate_peak_pressure));
  const double relief =
      Of(s.optimized, Reduction(s.initial.peak_pressure, s.optimized.peak_pressure));
  j["peak_relief_percent"] = Number(relief);
  if (IsShoe(s)) {
    const OffloadingReading reading = ReadOffloading(s);
    Json offloading = Json::object();
    offloading["criterion"] = "peak reduction > 30 % or peak < 200 kPa (Bus et al. 2011, IWGDF)";
    offloading["reading"] = reading.name();
    offloading["initial_peak_Pa"] = Number(reading.initial);
    offloading["peak_Pa"] = Number(Of(s.optimized, reading.optimized));
    offloading["peak_reduction_percent"] = Number(Of(s.optimized, reading.relief()));
    offloading["peak_below_200kPa"] = fresh.ok && reading.optimized < kOffloadingPeak;
    offloading["met"] = fresh.ok && reading.met();
    j["offloading"] = offloading;
  }
  // Placement checks.
  Json checks = Json::array();
  for (const PlacementOutcome& c : s.checks) {
    Json entry = Json::object();
    entry["name"] = c.placement.name;
    entry["dx_m"] = c.placement.shift.x();
    entry["dz_m"] = c.placement.shift.z();
    entry["pitch_rad"] = c.placement.tilt.x();
    entry["tilt_rad"] = Json::array();
    for (int k = 0; k < 3; ++k) entry["tilt_rad"].push_back(c.placement.tilt[k]);
    entry["converged"] = c.ok;
    entry["initial_score"] = Number(c.ok ? c.initial_score : kNaN);
    entry["score"] = Number(c.ok ? c.score : kNaN);
    entry["reduction_percent"] = Number(c.ok ? c.ReductionPercent() : kNaN);
    if (!c.ok) entry["message"] = c.message;
    checks.push_back(entry);
  }
  j["placement_checks"] = checks;
  const double worst = WorstCheckReduction(s);
  j["worst_placement_reduction_percent"] = Number(worst);
  j["worst_placement_fraction_of_centred"] =
      Number(Of(s.optimized, worst / Reduction(phi0, fresh.phi)));
  // How the problem was posed.
  const DesignOptions& design = scenario.design;
  j["gamma"] = s.gamma;
  j["contact_stiffness_Pa_per_m"] = design.equilibrium.contact_stiffness;
  j["filter_radius_m"] = design.parameterization == DesignParameterization::kFiltered ||
                                 design.parameterization == DesignParameterization::kSpline
                             ? Json(design.filter_radius)
                             : Json();
  j["pressure_smoothing_radius_m"] = design.pressure.smoothing_radius;
  j["wall_s"] = s.wall_seconds;
  j["body_vertices"] = static_cast<long>(scenario.body->rest().vertices.rows());
  j["support_vertices"] = static_cast<long>(scenario.support.vertices.rows());
  j["contact_vertices"] = fresh.ok ? Json(fresh.equilibrium.contact_vertices) : Json();
  j["initial_contact_vertices"] = initial.equilibrium.contact_vertices;
  j["initial_max_penetration_m"] = initial.equilibrium.max_penetration;
  j["optimized_max_penetration_m"] = Number(Of(s.optimized, fresh.equilibrium.max_penetration));
  Json pose = Json::object();
  pose["initial"] = Pose(s.initial);
  pose["fresh"] = Pose(s.optimized);
  pose["followed"] = Pose(s.followed);
  j["core_pose"] = pose;
  Json candidates = Json::array();
  for (size_t i = 0; i < s.candidate_phi.size(); ++i) {
    Json c = Json::object();
    c["optimizer_score"] = s.candidate_phi[i];
    c["fresh_score"] = Number(i < s.candidate_fresh_phi.size() ? s.candidate_fresh_phi[i] : kNaN);
    candidates.push_back(c);
  }
  j["candidates"] = candidates;
  j["kept_candidate"] = s.kept_candidate;
  j["evaluations"] = s.result.evaluations;
  j["failed_evaluations"] = s.result.failed_evaluations;
  j["newton_iterations"] = s.result.newton_iterations;
  // Where the optimisation's evaluations spent their time (those counted in `evaluations`;
  // seconds summed per evaluation, so parallel probes and placements exceed wall_s).
  j["time_split"] = TimingJson(s.result.timing);
  j["stop_reason"] = s.result.stop_reason;
  j["interrupted"] = s.interrupted;
  j["load_N"] = scenario.body->TotalLoad().norm();
  return j;
}

std::string SummaryMarkdown(const RunSummary& s) {
  const DesignEvaluation& initial = s.initial.evaluation;
  const DesignEvaluation& fresh = s.optimized.evaluation;
  const DesignEvaluation& followed = s.followed.evaluation;
  const double phi0 = initial.phi;
  auto triple = [&](const char* row, const char* format, double scale, double a, double b,
                    double c) {
    return std::string("| ") + row + " | " + Format(format, a * scale) + " | " +
           Format(format, b * scale) + " | " + Format(format, c * scale) + " |\n";
  };
  std::ostringstream md;
  md << "# ergo_optimize: " << s.scenario->name << "\n\n" << s.scenario->description << "\n\n";
  if (s.start != "initial")
    md << "The optimiser started from the " << s.start << " design (its objective "
       << Format("%.4g", s.start_score) << "); every score below is relative to the initial "
       << "design.\n\n";
  if (fresh.ok) {
    md << "**Placed afresh on the optimised design, the body scores φ " << Format("%.4g", fresh.phi)
       << ", " << Format("%.1f", Reduction(phi0, fresh.phi)) << " % below the initial design**";
    if (std::isfinite(s.followed_phi))
      md << " (on the path the optimiser followed: "
         << Format("%.1f", Reduction(phi0, s.followed_phi)) << " %)";
    md << ". The skin's side of the score, what the person feels, falls "
       << Format("%.1f", Reduction(initial.zeta_human, fresh.zeta_human)) << " %; the peak skin "
       << "pressure goes from " << Format("%.1f", s.initial.peak_pressure / 1e3) << " to "
       << Format("%.1f", s.optimized.peak_pressure / 1e3) << " kPa ("
       << Format("%.1f", Reduction(s.initial.peak_pressure, s.optimized.peak_pressure))
       << " % relief).\n\n";
  } else {
    md << "**The body placed afresh on the optimised design did not reach equilibrium: "
       << fresh.message << "**\n\n";
  }
  md << "| | initial | optimised, placed afresh | optimised, optimiser's path "
        "|\n|---|---|---|---|\n"
     << triple("score φ", "%.4g", 1, phi0, Of(s.optimized, fresh.phi), s.followed_phi)
     << triple("ζ (pressure term)", "%.4g", 1, initial.zeta, Of(s.optimized, fresh.zeta),
               Of(s.followed, followed.zeta))
     << triple("ζ, skin side", "%.4g", 1, initial.zeta_human, Of(s.optimized, fresh.zeta_human),
               Of(s.followed, followed.zeta_human))
     << triple("ζ, support side", "%.4g", 1, initial.zeta_support,
               Of(s.optimized, fresh.zeta_support), Of(s.followed, followed.zeta_support))
     << triple("peak skin pressure (kPa)", "%.1f", 1e-3, s.initial.peak_pressure,
               Of(s.optimized, s.optimized.peak_pressure), Of(s.followed, s.followed.peak_pressure))
     << triple("peak a 5 mm plate reads (kPa)", "%.1f", 1e-3, s.initial.plate_peak_pressure,
               Of(s.optimized, s.optimized.plate_peak_pressure),
               Of(s.followed, s.followed.plate_peak_pressure))
     << triple("skin contact area (cm²)", "%.1f", 1e4, s.initial.skin_contact_area,
               Of(s.optimized, s.optimized.skin_contact_area),
               Of(s.followed, s.followed.skin_contact_area))
     << triple("max penetration (mm)", "%.3f", 1e3, initial.equilibrium.max_penetration,
               Of(s.optimized, fresh.equilibrium.max_penetration),
               Of(s.followed, followed.equilibrium.max_penetration))
     << triple("skin vertices in contact", "%.0f", 1, initial.equilibrium.contact_vertices,
               Of(s.optimized, fresh.equilibrium.contact_vertices),
               Of(s.followed, followed.equilibrium.contact_vertices))
     << "\n";
  if (IsShoe(s) && fresh.ok) {
    const OffloadingReading reading = ReadOffloading(s);
    md << "Clinical reading (in-shoe offloading: peak reduction > 30 % or peak < 200 kPa, Bus et "
          "al. 2011), on "
       << (reading.on_plate ? "the peak a 5 mm plate reads" : "ergo's per-vertex peak") << ": "
       << (reading.met() ? "met" : "not met") << " — peak "
       << Format("%.1f", reading.optimized / 1e3) << " kPa, " << Format("%.1f", reading.relief())
       << " % below the flat sole";
    if (reading.on_plate) {
      md << " (ergo's per-vertex peak: " << Format("%.1f", s.optimized.peak_pressure / 1e3)
         << " kPa, "
         << Format("%.1f", Reduction(s.initial.peak_pressure, s.optimized.peak_pressure))
         << " % below)";
    }
    md << ".\n\n";
  }
  {
    const TissueCompression& a = s.initial.compression;
    md << "Tissue past the material's inversion threshold (a principal stretch below "
       << Format("%.2g", a.threshold) << ", more than " << Format("%.0f", 100 * (1 - a.threshold))
       << " % compression, where the pressure is the law's numerical extension): "
       << a.tets_beyond_threshold << " tets on the initial design (smallest stretch "
       << Format("%.3g", a.min_principal_stretch) << ")";
    if (fresh.ok) {
      const TissueCompression& b = s.optimized.compression;
      md << ", " << b.tets_beyond_threshold << " on the optimised one ("
         << Format("%.3g", b.min_principal_stretch) << ")";
    }
    md << ".\n\n";
  }
  const std::vector<double>&before = s.initial.region_shares, &after = s.optimized.region_shares;
  if (!before.empty()) {
    const LengthRegions& regions = s.scenario->regions;
    std::string names, bands;
    for (size_t k = 0; k < regions.names.size(); ++k) {
      names += (k ? " / " : "") + regions.names[k];
      const double begin = k ? regions.ends[k - 1] : 0;
      bands += (k ? ", " : "") + Format("%.0f", 100 * begin) + "–" +
               Format("%.0f", 100 * regions.ends[k]) + " %";
    }
    auto percents = [](const std::vector<double>& values) {
      std::string out;
      for (size_t k = 0; k < values.size(); ++k)
        out += (k ? " / " : "") + Format("%.1f", 100 * values[k]);
      return out + " %";
    };
    md << "Load split " << names << " (" << bands << " of the length from the "
       << (IsShoe(s) ? "heel" : "start") << "): " << percents(before) << " on the initial design"
       << (after.empty() ? std::string() : ", " + percents(after) + " on the optimised one")
       << "; centre of pressure at "
       << Format("%.1f", 100 * CentreFraction(s, s.initial.centre_of_pressure)) << " % of the "
       << "length (initial).\n\n";
  }
  if (!s.checks.empty()) {
    md << "Placement checks (the body placed afresh off the pose the optimiser saw; reduction "
          "against the initial design at the same placement):\n\n"
          "| placement | initial φ | optimised φ | reduction |\n|---|---|---|---|\n";
    for (const PlacementOutcome& c : s.checks) {
      md << "| " << c.placement.name << " | " << (c.ok ? Format("%.4g", c.initial_score) : "–")
         << " | " << (c.ok ? Format("%.4g", c.score) : "–") << " | "
         << (c.ok ? Format("%.1f", c.ReductionPercent()) + " %" : "did not converge") << " |\n";
    }
    md << "\nWorst placement: " << Format("%.1f", WorstCheckReduction(s)) << " % (centred "
       << Format("%.1f", Of(s.optimized, Reduction(phi0, fresh.phi))) << " %).\n\n";
  }
  const DesignOptions& design = s.scenario->design;
  md << "Table 1 columns: reduction " << Format("%.1f", Of(s.optimized, Reduction(phi0, fresh.phi)))
     << " % (afresh), smoothing strength γ " << Format("%.3g", s.gamma) << ", time "
     << Format("%.1f", s.wall_seconds) << " s, " << s.scenario->body->rest().vertices.rows()
     << " body vertices, " << s.scenario->support.vertices.rows() << " support vertices.\n\n"
     << "Contact stiffness κ " << Format("%.3g", design.equilibrium.contact_stiffness) << " Pa/m; "
     << (design.parameterization == DesignParameterization::kFiltered
             ? "design filter radius " + Format("%.1f", design.filter_radius * 1e3) + " mm"
         : design.parameterization == DesignParameterization::kSpline
             ? "design space a cubic B-spline lattice of knot spacing " +
                   Format("%.1f", design.filter_radius * 1e3) + " mm"
             : std::string("design filter radius none (raw vertices)"))
     << "; pressure smoothing "
     << (design.pressure.smoothing_radius > 0
             ? "radius " + Format("%.1f", design.pressure.smoothing_radius * 1e3) + " mm"
             : std::string("umbrella"))
     << "; evaluations placed " << s.placement
     << (s.robust_placements > 1
             ? ", objective averaged over " + std::to_string(s.robust_placements) + " placements"
             : std::string())
     << ".\n\n";
  if (!s.candidate_phi.empty()) {
    md << "Kept design: the best of " << s.candidate_phi.size()
       << " candidates placed afresh (candidate " << s.kept_candidate + 1 << ").\n\n";
  }
  if (!s.post_smoothing.empty()) md << s.post_smoothing << "\n\n";
  md << "Optimiser " << s.optimizer << ": " << s.result.evaluations << " evaluations ("
     << s.result.failed_evaluations << " failed), " << s.result.newton_iterations
     << " Newton iterations; stopped: " << s.result.stop_reason << ".\n\n"
     << "Time of those evaluations (summed per evaluation; summary.json's time_split): "
     << s.result.timing.BriefReport() << ".\n\n"
     << "Files: support_initial/optimized.{ply,stl} (millimetres; the STL is closed and "
        "print-ready), body_*.vtu and support_*.vtu (pressure_Pa, contact_force_N, "
        "displacement_m; the optimised ones placed afresh), history.csv, pressure_maps.png, "
        "pressure_histograms.png, displacement.png, phi_history.png.\n";
  return md.str();
}

}  // namespace ergo
