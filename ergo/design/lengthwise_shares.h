// How a pressure plate's masks split a foot's (or a seat's) load along its length: the
// skin's contact force in bands of the body's rest extent along z, each as a share of the
// whole. As for the centre of pressure (centre_of_pressure.h), each skin vertex's contact force
// f_i counts by its component along the load, w_i = −f_i·d̂; a vertex falls in the band of its
// rest position's fraction of that extent, from the smallest z or from the largest (a scan
// whose heel is at its largest z). The shoe's bands (FootRegionEnds): rearfoot, midfoot and
// forefoot below 30 %, 30–60 % and from 60 % of the foot's length from the heel, the split
// issue 14's targets use (standing barefoot: rearfoot 40–65 %, midfoot under 25 %).
// Metres, N.
#pragma once

#include <string>
#include <vector>

#include "ergo/body/layered_body.h"
#include "ergo/contact/surface_contact.h"

namespace ergo {

// The foot's bands' upper ends, fractions of its length from the heel, and their names.
inline std::vector<double> FootRegionEnds() { return {0.3, 0.6, 1.0}; }
inline std::vector<std::string> FootRegionNames() { return {"rearfoot", "midfoot", "forefoot"}; }

struct LengthwiseShares {
  std::vector<double> shares;  // one per band, summing to 1; empty when nothing touches
  double normal_force = 0;     // Σ w_i, N
};

// `ends`: the bands' upper ends, increasing, the last 1 (CHECKed); the first band begins at 0.
LengthwiseShares ComputeLengthwiseShares(const LayeredBody& body, const SurfaceContacts& contacts,
                                         const std::vector<double>& ends, bool from_min_z);

}  // namespace ergo
