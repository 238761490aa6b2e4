#include "tools/ergo_simulate/plot_data.h"

#include "ergo/design/centre_of_pressure.h"
#include "ergo/design/lengthwise_shares.h"
#include "tools/common/pressure_view.h"

namespace ergo {

Json SimulationPlotData(const LayeredBody& body, const BodyState& state,
                        const ContactPressures& pressures, const TissueCompression& compression,
                        const LengthReading& reading, const Json& summary,
                        const std::string& title) {
  const PressureView view = ViewAlongLoad(body);
  Json data = Json::object();
  data["tool"] = "ergo_simulate";
  data["title"] = title;
  data["view"] = ViewJson(view);
  data["skin"] = SkinPressureMap(body, state, pressures.human.pressure, view);
  const CentreOfPressure cop = ComputeCentreOfPressure(body, state, pressures.contacts);
  if (cop.normal_force > 0) {
    data["centre_of_pressure2d"] = Json::array({cop.point.dot(view.u), cop.point.dot(view.v)});
  }
  // Where the tissue is squeezed past its material law (tissue_compression.h): its pressure
  // there is the law's extension, and the map says so.
  Json crushed = Json::array();
  for (const Eigen::Vector3d& p : compression.beyond_threshold_points)
    crushed.push_back(Json::array({p.dot(view.u), p.dot(view.v)}));
  data["crushed_points2d"] = crushed;
  const Json* shares = nullptr;
  if (const Json* split = FindMember(summary, "region_shares"))
    shares = FindMember(*split, "shares");
  if (reading.foot_regions && shares) {
    Json bands =
        LengthBands(body, view, FootRegionNames(), FootRegionEnds(), reading.heel_at_min_z);
    if (!bands.is_null()) {
      for (Json& band : bands) band["share"] = shares->at(band["name"].get<std::string>());
      data["regions"] = bands;
    }
  }
  return data;
}

}  // namespace ergo
