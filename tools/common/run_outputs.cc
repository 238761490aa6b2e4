#include "tools/common/run_outputs.h"

#include <cmath>
#include <filesystem>

#include <Eigen/Geometry>

#include "ergo/design/equilibrium_report.h"
#include "ergo/design/lengthwise_shares.h"
#include "ergo/ergonomics/pressure_statistics.h"
#include "ergo/mesh/mesh_io.h"

namespace ergo {
namespace {

// An orthonormal basis (u, v) of the plane perpendicular to the load, and axis names.
struct View {
  Eigen::Vector3d u, v, down;
  std::string u_name, v_name;
};

View ViewAlongLoad(const LayeredBody& body) {
  View view;
  const Eigen::Vector3d load = body.TotalLoad();
  view.down = load.norm() > 0 ? load.normalized() : Eigen::Vector3d(0, -1, 0);
  // Prefer world axes for readable labels when the load is along one of them.
  Eigen::Index axis;
  view.down.cwiseAbs().maxCoeff(&axis);
  const char* names[3] = {"x", "y", "z"};
  const int a = static_cast<int>((axis + 1) % 3), b = static_cast<int>((axis + 2) % 3);
  view.u = Eigen::Vector3d::Unit(std::min(a, b));
  view.v = Eigen::Vector3d::Unit(std::max(a, b));
  view.u = (view.u - view.u.dot(view.down) * view.down).normalized();
  view.v = view.down.cross(view.u).normalized();
  view.u_name = names[std::min(a, b)];
  view.v_name = names[std::max(a, b)];
  return view;
}

Json Points2d(const Vertices& points, const View& view) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    Json p = Json::array();
    p.push_back(points.row(i).dot(view.u.transpose()));
    p.push_back(points.row(i).dot(view.v.transpose()));
    out.push_back(p);
  }
  return out;
}

// Skin triangles facing the support (outward normal along the load), with vertex pressure.
Json SkinView(const LayeredBody& body, const DesignReport& report, const View& view) {
  const Skin& skin = body.skin();
  const Vertices positions = DeformedPositions(body, report.evaluation.equilibrium.state);
  const TriMesh surface = skin.RestSurface(positions);
  Json triangles = Json::array();
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(f, 0));
    const Eigen::Vector3d b = surface.vertices.row(surface.triangles(f, 1));
    const Eigen::Vector3d c = surface.vertices.row(surface.triangles(f, 2));
    if ((b - a).cross(c - a).dot(view.down) <= 0) continue;
    Json t = Json::array();
    for (int k = 0; k < 3; ++k) t.push_back(surface.triangles(f, k));
    triangles.push_back(t);
  }
  Json pressure = Json::array();
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i)
    pressure.push_back(report.pressures.human.pressure[i]);
  Json out = Json::object();
  out["points2d"] = Points2d(surface.vertices, view);
  out["triangles"] = triangles;
  out["pressure"] = pressure;
  return out;
}

}  // namespace

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
  report.centre_of_pressure = ComputeCentreOfPressure(
      problem.body(), report.evaluation.equilibrium.state, report.pressures.contacts);
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
  const View view = ViewAlongLoad(body);
  Json data = Json::object();
  data["scenario"] = scenario.name;
  Json view_json = Json::object();
  Json axes = Json::array();
  axes.push_back(view.u_name);
  axes.push_back(view.v_name);
  view_json["axes"] = axes;
  data["view"] = view_json;
  for (const auto& [name, report] :
       {std::pair<const char*, const DesignReport*>{"initial", &initial},
        std::pair<const char*, const DesignReport*>{"optimized", &optimized}}) {
    Json entry = Json::object();
    entry["skin"] = SkinView(body, *report, view);
    data[name] = entry;
  }
  // The scenario's regions along z (the shoe's rearfoot, midfoot, forefoot) when the map's
  // second axis is z: each band's extent on that axis (the rest foot's, m) and its share of
  // the load on each design, for the maps to mark.
  const LengthRegions& regions = scenario.regions;
  if (!regions.names.empty() && view.v_name == std::string("z") && view.v.z() > 0) {
    const Vertices& rest = body.rest().vertices;
    const double min_z = rest.col(2).minCoeff(), extent = rest.col(2).maxCoeff() - min_z;
    auto at = [&](double fraction) {
      return min_z + extent * (regions.from_min_z ? fraction : 1 - fraction);
    };
    const std::vector<double>&before = initial.region_shares, &after = optimized.region_shares;
    Json bands = Json::array();
    for (size_t k = 0; k < regions.names.size(); ++k) {
      Json band = Json::object();
      band["name"] = regions.names[k];
      band["v_from"] = at(k ? regions.ends[k - 1] : 0);
      band["v_to"] = at(regions.ends[k]);
      band["initial_share"] = k < before.size() ? Json(before[k]) : Json();
      band["optimized_share"] = k < after.size() ? Json(after[k]) : Json();
      bands.push_back(band);
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
