// The skin's contact pressure seen from the support, as the picture scripts draw it
// (tools/plot_results.py, tools/plot_simulation.py): a view along the load, the skin
// triangles that face the support with each skin vertex's pressure, and the foot's length
// bands (rearfoot, midfoot, forefoot) as extents along the map's second axis.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/mesh/json.h"

namespace ergo {

// An orthonormal basis (u, v) of the plane perpendicular to the load, with axis names: the
// world axes when the load runs along one of them (gravity along −y: u = x, v = z).
struct PressureView {
  Eigen::Vector3d u, v, down;
  std::string u_name, v_name;
};

PressureView ViewAlongLoad(const LayeredBody& body);

// {"axes": [u_name, v_name]}.
Json ViewJson(const PressureView& view);

// Each point's (u, v), metres.
Json Points2d(const Vertices& points, const PressureView& view);

// The deformed skin at `state`: {"points2d", "triangles" (those whose outward normal points
// along the load, i.e. towards the support), "pressure" (Pa, one per skin vertex)}.
// `skin_pressure` has one entry per skin vertex.
Json SkinPressureMap(const LayeredBody& body, const BodyState& state,
                     const Eigen::VectorXd& skin_pressure, const PressureView& view);

// Length bands along z for a map whose second axis is +z: each band's name and its extent
// (v_from, v_to, m) on the rest body's z extent, the bands' fractions `ends` counted from the
// smallest z (from_min_z) or the largest. Empty (null) when the map's second axis is not +z.
// The caller adds each band's share.
Json LengthBands(const LayeredBody& body, const PressureView& view,
                 const std::vector<std::string>& names, const std::vector<double>& ends,
                 bool from_min_z);

}  // namespace ergo
