#include "tools/common/pressure_view.h"

#include <algorithm>

#include <glog/logging.h>
#include <Eigen/Geometry>

namespace ergo {

PressureView ViewAlongLoad(const LayeredBody& body) {
  PressureView view;
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

Json ViewJson(const PressureView& view) {
  Json out = Json::object();
  out["axes"] = Json::array({view.u_name, view.v_name});
  return out;
}

Json Points2d(const Vertices& points, const PressureView& view) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    out.push_back(Json::array(
        {points.row(i).dot(view.u.transpose()), points.row(i).dot(view.v.transpose())}));
  return out;
}

Json SkinPressureMap(const LayeredBody& body, const BodyState& state,
                     const Eigen::VectorXd& skin_pressure, const PressureView& view) {
  const Skin& skin = body.skin();
  CHECK_EQ(skin_pressure.size(), skin.vertices.size());
  const TriMesh surface = skin.RestSurface(DeformedPositions(body, state));
  Json triangles = Json::array();
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(f, 0));
    const Eigen::Vector3d b = surface.vertices.row(surface.triangles(f, 1));
    const Eigen::Vector3d c = surface.vertices.row(surface.triangles(f, 2));
    if ((b - a).cross(c - a).dot(view.down) <= 0) continue;
    triangles.push_back(
        Json::array({surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2)}));
  }
  Json pressure = Json::array();
  for (Eigen::Index i = 0; i < skin_pressure.size(); ++i) pressure.push_back(skin_pressure[i]);
  Json out = Json::object();
  out["points2d"] = Points2d(surface.vertices, view);
  out["triangles"] = triangles;
  out["pressure"] = pressure;
  return out;
}

Json LengthBands(const LayeredBody& body, const PressureView& view,
                 const std::vector<std::string>& names, const std::vector<double>& ends,
                 bool from_min_z) {
  CHECK_EQ(names.size(), ends.size());
  if (names.empty() || view.v_name != "z" || !(view.v.z() > 0)) return Json();
  const Vertices& rest = body.rest().vertices;
  const double min_z = rest.col(2).minCoeff(), extent = rest.col(2).maxCoeff() - min_z;
  auto at = [&](double fraction) {
    return min_z + extent * (from_min_z ? fraction : 1 - fraction);
  };
  Json bands = Json::array();
  for (size_t k = 0; k < names.size(); ++k) {
    Json band = Json::object();
    band["name"] = names[k];
    band["v_from"] = at(k ? ends[k - 1] : 0);
    band["v_to"] = at(ends[k]);
    bands.push_back(band);
  }
  return bands;
}

}  // namespace ergo
