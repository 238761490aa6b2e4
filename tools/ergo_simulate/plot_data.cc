#include "tools/ergo_simulate/plot_data.h"

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
  if (const Json* point = FindMember(summary, "centre_of_pressure_m")) {  // when in contact
    const Eigen::Vector3d cop(point->at(0).get<double>(), point->at(1).get<double>(),
                              point->at(2).get<double>());
    data["centre_of_pressure2d"] = Json::array({cop.dot(view.u), cop.dot(view.v)});
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
