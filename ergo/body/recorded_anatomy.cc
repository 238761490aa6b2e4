#include "ergo/body/recorded_anatomy.h"

#include <cmath>

#include "ergo/mesh/input_error.h"

namespace ergo {

RecordedAnatomy ReadRecordedAnatomy(const Json& source, const std::string& file) {
  RecordedAnatomy recorded;
  const Json* anatomy = source.is_object() ? FindMember(source, "anatomy") : nullptr;
  if (anatomy == nullptr) return recorded;
  if (!anatomy->is_string()) {
    throw InputError(file, "source.anatomy", "is not a string", "rebuild the body with ergo_body");
  }
  recorded.anatomy = ParseAnatomy(anatomy->get<std::string>(), file + ": source.anatomy");
  const Json* landmarks = FindMember(source, "landmarks");
  if (recorded.anatomy != Anatomy::kFoot || landmarks == nullptr) return recorded;
  if (!landmarks->is_array()) {
    throw InputError(file, "source.landmarks", "is not an array",
                     "rebuild the body with ergo_body");
  }
  std::optional<double> heel_z, toe_z;
  for (const Json& mark : *landmarks) {
    const std::string where = file + ": source.landmarks";
    if (!mark.is_object()) {
      throw InputError(file, "source.landmarks", "holds an entry that is not an object",
                       "rebuild the body with ergo_body");
    }
    const std::string& name = GetString(mark, "name", where);
    const Json& point = GetMember(mark, "point_m", where);
    if (!point.is_array() || point.size() != 3 || !point[2].is_number() ||
        !std::isfinite(point[2].get<double>())) {
      throw InputError(file, "landmark \"" + name + "\"", "point_m is not three finite numbers",
                       "rebuild the body with ergo_body");
    }
    if (name == "heel") heel_z = point[2].get<double>();
    if (name == "toe tip") toe_z = point[2].get<double>();
  }
  if (heel_z && toe_z && *heel_z != *toe_z)
    recorded.heel_end = *heel_z < *toe_z ? HeelEnd::kMinZ : HeelEnd::kMaxZ;
  const Json* eversion = FindMember(source, "heel_eversion_deg");
  const Json* side = FindMember(source, "medial_side");
  if (eversion != nullptr && side != nullptr) {
    if (!eversion->is_number() || !std::isfinite(eversion->get<double>()) ||
        std::abs(eversion->get<double>()) > 90) {
      throw InputError(file, "source.heel_eversion_deg", "is not an angle in degrees",
                       "rebuild the body with ergo_body");
    }
    if (!side->is_string() ||
        (side->get<std::string>() != "+x" && side->get<std::string>() != "-x")) {
      throw InputError(file, "source.medial_side", "is neither \"+x\" nor \"-x\"",
                       "rebuild the body with ergo_body");
    }
    recorded.heel = ScannedHeel{eversion->get<double>() * M_PI / 180,
                                side->get<std::string>() == "+x" ? 1.0 : -1.0};
  }
  return recorded;
}

}  // namespace ergo
