#include "tools/common/run_outputs.h"

#include <cmath>
#include <filesystem>

#include <Eigen/Geometry>

#include "ergo/design/equilibrium_report.h"
#include "ergo/design/lengthwise_shares.h"
#include "ergo/ergonomics/plate_reading.h"
#include "ergo/ergonomics/pressure_statistics.h"
#include "ergo/mesh/mesh_io.h"
#include "tools/common/pressure_view.h"

namespace ergo {
DesignReport ReportEvaluation(const DesignProblem& problem, const Eigen::VectorXd& x,
                              DesignEvaluation evaluation, const LengthRegions& regions) {
  DesignReport report;
  report.x = x;
  report.support = problem.SupportAt(x);
  report.evaluation = std::move(evaluation);
  if (!report.evaluation.ok) return report;
  report.pressures = report.evaluation.pressures;
  const PressureStatistics skin =
      ComputePressureStatistics(report.pressures.human.pressure, problem.body().skin().rest_areas);
  report.peak_pressure = skin.peak;
  report.skin_contact_area = skin.contact_area;
  const BodyState& state = report.evaluation.equilibrium.state;
  report.compression = MeasureTissueCompression(problem.body(), state);
  if (LoadSeenAlongY(problem.body().TotalLoad())) {
    report.plate_peak_pressure =
        ComputePlatePeak(SkinMapFromBelow(problem.body(), DeformedPositions(problem.body(), state),
                                          report.pressures.human.pressure))
            .pressure;
  }
  report.centre_of_pressure =
      ComputeCentreOfPressure(problem.body(), state, report.pressures.contacts);
  if (!regions.names.empty()) {
    report.region_shares = ComputeLengthwiseShares(problem.body(), report.pressures.contacts,
                                                   regions.ends, regions.from_min_z)
                               .shares;
  }
  return report;
}

DesignReport ReportDesign(DesignProblem& problem, const Eigen::VectorXd& x,
                          const LengthRegions& regions) {
  return ReportEvaluation(problem, x, problem.Evaluate(x, false), regions);
}

void WriteDesignVtus(const std::string& dir, const std::string& tag, const LayeredBody& body,
                     const DesignReport& report, const Vertices& initial_support,
                     VtuEncoding vtu_encoding) {
  const std::filesystem::path out(dir);
  WriteDeformedBodyVtu((out / ("body_" + tag + ".vtu")).string(), body,
                       report.evaluation.equilibrium.state, report.pressures, vtu_encoding);
  const std::shared_ptr<const ElasticPart>& foam = report.evaluation.soft_support;
  if (!foam) {
    WriteSupportVtu((out / ("support_" + tag + ".vtu")).string(), report.support, report.pressures,
                    initial_support, vtu_encoding);
    return;
  }
  // A soft support: its surface deformed under the body (displacement from the initial rest
  // shape) and its solid with stress and strain.
  const Vertices positions = SoftSupportPositions(*foam, report.evaluation.equilibrium.state);
  WriteSupportVtu((out / ("support_" + tag + ".vtu")).string(),
                  SoftSupportSurface(*foam, report.support, positions), report.pressures,
                  initial_support, vtu_encoding);
  WriteSoftSupportVtu((out / ("support_solid_" + tag + ".vtu")).string(), *foam, positions,
                      vtu_encoding);
}

void WriteSupportMeshes(const std::string& dir, const std::string& tag, const TriMesh& support) {
  const std::filesystem::path out(dir);
  WriteOptions millimetres;
  millimetres.unit = LengthUnit::kMillimetre;
  WriteTriMesh((out / ("support_" + tag + ".ply")).string(), support, millimetres);
  millimetres.encoding = Encoding::kBinary;
  WriteTriMesh((out / ("support_" + tag + ".stl")).string(), support, millimetres);
}

void WriteDesignFiles(const std::string& dir, const std::string& tag, const LayeredBody& body,
                      const DesignReport& report, const Vertices& initial_support,
                      VtuEncoding vtu_encoding) {
  WriteDesignVtus(dir, tag, body, report, initial_support, vtu_encoding);
  WriteSupportMeshes(dir, tag, report.support);
}

Json PlotData(const Scenario& scenario, const DesignReport& initial,
              const DesignReport& optimized) {
  const LayeredBody& body = *scenario.body;
  const PressureView view = ViewAlongLoad(body);
  Json data = Json::object();
  data["scenario"] = scenario.name;
  data["view"] = ViewJson(view);
  for (const auto& [name, report] :
       {std::pair<const char*, const DesignReport*>{"initial", &initial},
        std::pair<const char*, const DesignReport*>{"optimized", &optimized}}) {
    Json entry = Json::object();
    entry["skin"] = SkinPressureMap(body, report->evaluation.equilibrium.state,
                                    report->pressures.human.pressure, view);
    // Tets squeezed past the material's law (tissue_compression.h), for the map to mark.
    Json crushed = Json::array();
    for (const Eigen::Vector3d& p : report->compression.beyond_threshold_points)
      crushed.push_back(Json::array({p.dot(view.u), p.dot(view.v)}));
    entry["crushed_points2d"] = crushed;
    data[name] = entry;
  }
  // The scenario's regions along z (the shoe's rearfoot, midfoot, forefoot) when the map's
  // second axis is z, with each band's share of the load on each design, for the maps to mark.
  const LengthRegions& regions = scenario.regions;
  Json bands = LengthBands(body, view, regions.names, regions.ends, regions.from_min_z);
  if (!bands.is_null()) {
    const std::vector<double>&before = initial.region_shares, &after = optimized.region_shares;
    for (size_t k = 0; k < bands.size(); ++k) {
      bands[k]["initial_share"] = k < before.size() ? Json(before[k]) : Json();
      bands[k]["optimized_share"] = k < after.size() ? Json(after[k]) : Json();
    }
    data["regions"] = bands;
  }
  // The designed region: support triangles whose corners are all active.
  const std::vector<bool>& active = scenario.design.active;
  Json triangles = Json::array(), displacement = Json::array();
  for (Eigen::Index f = 0; f < initial.support.triangles.rows(); ++f) {
    bool all = true;
    for (int k = 0; k < 3; ++k)
      all = all && (active.empty() || active[initial.support.triangles(f, k)]);
    if (!all) continue;
    Json t = Json::array();
    for (int k = 0; k < 3; ++k) t.push_back(initial.support.triangles(f, k));
    triangles.push_back(t);
  }
  for (Eigen::Index v = 0; v < initial.support.vertices.rows(); ++v)
    displacement.push_back(
        1e3 * (optimized.support.vertices.row(v) - initial.support.vertices.row(v)).norm());
  Json support_view = Json::object();
  support_view["points2d"] = Points2d(initial.support.vertices, view);
  support_view["triangles"] = triangles;
  support_view["displacement_mm"] = displacement;
  data["support_displacement"] = support_view;
  return data;
}

}  // namespace ergo
