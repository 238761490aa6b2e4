#include "tools/ergo_simulate/length_reading.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gflags/gflags.h>

#include "ergo/body/body_directory.h"
#include "ergo/body/recorded_anatomy.h"
#include "ergo/design/centre_of_pressure.h"
#include "ergo/design/lengthwise_shares.h"
#include "ergo/mesh/input_error.h"
#include "problems/load_point.h"
#include "problems/stance_roll.h"
#include "tools/common/flag_checks.h"

DEFINE_string(load_point, "none",
              "the whole load's line of action through the point at this fraction of the "
              "body's length from its heel (back) end, across at the core's centre, made a "
              "torque on the core and added to --external_torque (0.445: a foot in quiet "
              "standing, as ergo_optimize's shoe); none");
DEFINE_string(heel_end, "auto",
              "the end of z the length runs from, for --load_point and --regions: min_z, "
              "max_z, or auto (the body's landmarks when it was built with --anatomy=foot, "
              "else the end whose quarter reaches higher, the ankle)");
DEFINE_string(regions, "auto",
              "the load's split along the length in summary.json: foot (rearfoot, midfoot, "
              "forefoot: below 30 %, 30-60 % and from 60 % of the length from the heel), "
              "none, or auto (foot for a body built with --anatomy=foot)");

DEFINE_string(roll, "0",
              "the body turned about its length (z) through its core's centre before it is "
              "placed, degrees (> 0 turns +x up); or stance: the roll that stands a foot's "
              "heel bisector at --calcaneal_stance (as ergo_optimize's --shoe_roll=stance)");
DEFINE_double(calcaneal_stance, 6.07,
              "with --roll=stance: the resting calcaneal stance position, degrees everted "
              "(< 0 inverted); default the healthy adults' mean, 6.07 +- 2.7 (Sobel et al. 1999)");
DEFINE_string(foot_side, "auto",
              "with --roll=stance: left, right, or auto (the medial side is where the "
              "midfoot's underside is higher, the arch)");

namespace ergo {
namespace {
constexpr double kDegree = StanceRoll::kDegree;
constexpr double kMaxRoll = 30 * kDegree;
}  // namespace

LengthReading ParseLengthFlags() {
  LengthReading reading;
  if (FLAGS_load_point != "none") {
    char* end = nullptr;
    const double value = std::strtod(FLAGS_load_point.c_str(), &end);
    if (end == FLAGS_load_point.c_str() || *end != '\0' || !(value >= 0 && value <= 1)) {
      throw InputError("--load_point", "",
                       "'" + FLAGS_load_point + "' is neither a fraction in [0, 1] nor none",
                       "e.g. 0.445 (a foot in quiet standing)");
    }
    reading.load_point = value;
  }
  if (FLAGS_regions != "auto" && FLAGS_regions != "foot" && FLAGS_regions != "none") {
    throw InputError("--regions", "", "'" + FLAGS_regions + "' is not foot, none or auto",
                     "use --regions=foot, none or auto");
  }
  reading.foot_regions = FLAGS_regions == "foot";
  reading.auto_regions = FLAGS_regions == "auto";
  reading.heel_end = ParseHeelEnd(FLAGS_heel_end, "--heel_end");
  reading.foot_side = ParseFootSide(FLAGS_foot_side, "--foot_side");
  RequireInRange("calcaneal_stance", FLAGS_calcaneal_stance, -30, 30,
                 "the resting calcaneal stance position in degrees everted, e.g. 6.07");
  reading.calcaneal_stance = FLAGS_calcaneal_stance * kDegree;
  reading.stance_roll = FLAGS_roll == "stance";
  for (const char* flag : {"calcaneal_stance", "foot_side"}) {
    if (!reading.stance_roll && !gflags::GetCommandLineFlagInfoOrDie(flag).is_default) {
      throw InputError(std::string("--") + flag, "", "is only read with --roll=stance",
                       "add --roll=stance or drop the flag");
    }
  }
  if (!reading.stance_roll) {
    char* end = nullptr;
    const double degrees = std::strtod(FLAGS_roll.c_str(), &end);
    if (end == FLAGS_roll.c_str() || *end != '\0' || !(std::abs(degrees) <= 30)) {
      throw InputError("--roll", "", "'" + FLAGS_roll + "' is not an angle within ±30 degrees",
                       "give e.g. 0 or 5.4, or stance");
    }
    reading.roll = degrees * kDegree;
  }
  return reading;
}

void ResolveLengthReading(const std::string& body_dir, const LayeredBody& body,
                          LengthReading* reading) {
  const std::string record = (std::filesystem::path(body_dir) / kBodyJsonFile).string();
  const RecordedAnatomy recorded =
      ReadRecordedAnatomy(GetMember(ReadJsonFile(record), "source", record), record);
  if (reading->auto_regions) reading->foot_regions = recorded.anatomy == Anatomy::kFoot;
  if (reading->load_point || reading->foot_regions || reading->stance_roll) {
    const HeelEnd end = reading->heel_end != HeelEnd::kAuto
                            ? reading->heel_end
                            : recorded.heel_end.value_or(HeelEnd::kAuto);
    reading->heel_at_min_z = HeelAtMinZ(body.rest().vertices, end, "--heel_end");
  }
  if (reading->stance_roll) {
    // The heel as bisected on the scan before meshing (body.json) unless the side is stated;
    // else on the body's skin.
    AnatomyOptions foot;
    foot.heel_end = reading->heel_at_min_z ? HeelEnd::kMinZ : HeelEnd::kMaxZ;
    foot.foot_side = reading->foot_side;
    reading->stance =
        recorded.heel && reading->foot_side == FootSide::kAuto
            ? StanceRollFrom(*recorded.heel, reading->calcaneal_stance, kMaxRoll, "the scan",
                             "--roll=stance")
            : FindStanceRoll(body, foot, reading->calcaneal_stance, kMaxRoll, "--roll=stance");
    reading->roll = reading->stance->roll;
  }
}

void ApplyLoadPoint(const LengthReading& reading, LayeredBody* body) {
  if (!reading.load_point) return;
  const Eigen::Vector3d force = body->options().external_force;
  const Eigen::Vector3d torque =
      body->options().external_torque +
      LoadPointTorque(*body, force, *reading.load_point,
                      reading.heel_at_min_z ? HeelEnd::kMinZ : HeelEnd::kMaxZ, "--load_point");
  body->SetExternalWrench(force, torque);
}

std::string ReportLengthReading(const LengthReading& reading, const LayeredBody& body,
                                const BodyState& state, const SurfaceContacts& contacts,
                                Json* summary) {
  const char* heel_end = reading.heel_at_min_z ? "min_z" : "max_z";
  if (reading.load_point) {
    const Eigen::Vector3d& torque = body.options().external_torque;
    Json load = Json::object();
    load["fraction"] = *reading.load_point;
    load["heel_end"] = heel_end;
    load["external_torque_Nm"] = Json::array({torque.x(), torque.y(), torque.z()});
    (*summary)["load_point"] = load;
  }
  if (reading.roll != 0 || reading.stance_roll) {
    Json roll = Json::object();
    roll["degrees"] = reading.roll / kDegree;
    roll["rule"] = reading.stance_roll ? "stance" : "given";
    if (reading.stance) {
      roll["heel_eversion_deg"] = reading.stance->heel_eversion / kDegree;
      roll["calcaneal_stance_deg"] = reading.stance->calcaneal_stance / kDegree;
    }
    (*summary)["roll"] = roll;
  }
  if (!reading.foot_regions) return "";
  const std::vector<double> ends = FootRegionEnds();
  const LengthwiseShares split =
      ComputeLengthwiseShares(body, contacts, ends, reading.heel_at_min_z);
  if (split.shares.empty()) return "";
  const std::vector<std::string> names = FootRegionNames();
  Json shares = Json::object();
  for (size_t k = 0; k < split.shares.size(); ++k) shares[names[k]] = split.shares[k];
  Json regions = Json::object();
  regions["ends"] = Json::array({ends[0], ends[1], ends[2]});
  regions["heel_end"] = heel_end;
  regions["shares"] = shares;
  (*summary)["region_shares"] = regions;
  const CentreOfPressure cop = ComputeCentreOfPressure(body, state, contacts);
  const double from_heel = reading.heel_at_min_z ? cop.z_fraction : 1 - cop.z_fraction;
  (*summary)["centre_of_pressure_heel_fraction"] = from_heel;
  char line[256];
  std::snprintf(line, sizeof line,
                "load split rearfoot / midfoot / forefoot (0-30 %%, 30-60 %%, 60-100 %% of the "
                "length from the heel): %.1f / %.1f / %.1f %%; centre of pressure at %.1f %% "
                "of the length",
                100 * split.shares[0], 100 * split.shares[1], 100 * split.shares[2],
                100 * from_heel);
  return line;
}

}  // namespace ergo
