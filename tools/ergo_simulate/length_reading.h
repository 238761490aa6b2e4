// ergo_simulate's reading of a body along its length, the way ergo_optimize reads the shoe's
// foot: --load_point puts the whole load's line of action at a fraction of the body's length
// from its heel (back) end, as a torque on the core (problems/load_point.h); --regions adds the
// load's split (rearfoot, midfoot, forefoot: ergo/design/lengthwise_shares.h) and the centre
// of pressure's fraction from the heel to summary.json. The heel end comes from --heel_end,
// else from the body directory's landmarks (a body built with --anatomy=foot), else from the
// ankle (the end whose quarter reaches higher).
#pragma once

#include <optional>
#include <string>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/contact/surface_contact.h"
#include "ergo/mesh/json.h"
#include "problems/stance_roll.h"

namespace ergo {

struct LengthReading {
  std::optional<double> load_point;   // fraction of the length from the heel end
  bool foot_regions = false;          // report the foot's split
  bool auto_regions = false;          // --regions=auto: the foot's split for a recorded foot
  HeelEnd heel_end = HeelEnd::kAuto;  // --heel_end
  bool heel_at_min_z = true;  // set by ResolveLengthReading when load_point or foot_regions is
  FootSide foot_side = FootSide::kAuto;  // --foot_side, for the stance roll's medial side
  // --roll: the body turned about its length (z) through its core's centre before it is
  // placed, rad (> 0 turns +x up); with stance_roll, the roll that stands a foot's heel at
  // calcaneal_stance (problems/stance_roll.h), set by ResolveLengthReading.
  double roll = 0;
  bool stance_roll = false;
  double calcaneal_stance = 0;       // rad everted
  std::optional<StanceRoll> stance;  // how the stance roll was found (ResolveLengthReading)
};

// Reads --load_point, --heel_end, --regions, --roll, --calcaneal_stance and --foot_side
// (before any work: a bad value is refused at once). Throws InputError naming the flag.
LengthReading ParseLengthFlags();

// Settles what needs the body: the foot's regions for --regions=auto (a body built with
// --anatomy=foot), the heel end, and the stance roll. Throws InputError naming --heel_end (or
// body.json) when the heel end is needed and cannot be told.
void ResolveLengthReading(const std::string& body_dir, const LayeredBody& body,
                          LengthReading* reading);

// With a load point, adds its torque to the body's external torque; otherwise nothing.
void ApplyLoadPoint(const LengthReading& reading, LayeredBody* body);

// Adds "load_point" ({fraction, heel_end, external_torque_Nm}), "roll" ({degrees, rule, and
// for the stance heel_eversion_deg and calcaneal_stance_deg}) when the body was turned, and, with
// the foot's regions, "region_shares" ({ends, shares by name}) and
// "centre_of_pressure_heel_fraction" to `summary`. Returns one line for people ("" when there is
// nothing to say).
std::string ReportLengthReading(const LengthReading& reading, const LayeredBody& body,
                                const BodyState& state, const SurfaceContacts& contacts,
                                Json* summary);

}  // namespace ergo
