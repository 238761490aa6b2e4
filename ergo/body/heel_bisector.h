// The heel's bisector seen from behind: the line a clinician draws through the middle of the
// heel's outline to read the resting calcaneal stance position (RCSP: the angle the heel's
// bisection makes with the vertical when standing; everted, or valgus, when its top leans
// towards the other foot). Measured on a foot's skin in ergo's frame (y up, the length along
// z): the skin is sliced at heights above the heel's lowest point, each slice's extent across
// the foot (x) over the rear of the foot is the outline seen from behind, and a least-squares
// line through the slices' mid-points is the bisector. The line is the skin's, drawn once: a
// roll of the whole foot turns it with the foot (problems/stance_roll.h).
#pragma once

#include <string>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct HeelBisectorOptions {
  double rear_fraction = 0.12;  // the heel: this rear fraction of the foot's length (~3 cm)
  // Heights above the heel's lowest skin: from above the plantar pad's rounding to below the
  // ankle's malleoli, m.
  double lowest_height = 0.006, highest_height = 0.05;
  double height_step = 0.002;  // m between slices
  int min_slices = 4;          // fewer slices with an outline: the heel cannot be bisected
};

// A foot's heel as read on its scan, all a stance needs: the bisector's eversion (rad, > 0
// everted) and the foot's medial side (+1: +x, −1: −x), which says which way is eversion.
struct ScannedHeel {
  double eversion = 0;
  double medial_sign = 1;
};

struct HeelBisector {
  // Angle of the bisector from the vertical, rad: > 0 everted (its top medial of its base).
  double eversion = 0;
  // The bisector's lean: dx/dy, the across-foot shift of the mid-points per metre of height.
  double lean = 0;
  int slices = 0;           // slices through which it was fitted
  double rms_residual = 0;  // of the mid-points about the line, m
  double heel_floor_y = 0;  // the heel's lowest skin, m
};

// The bisector of `foot`'s heel, at its smallest z if `heel_at_min_z` (else its largest),
// with the medial side at +x if `medial_sign` > 0 (else −x). Throws InputError naming
// `source` when fewer than `min_slices` slices cut the heel (a scan with no heel, or holes).
HeelBisector MeasureHeelBisector(const TriMesh& foot, bool heel_at_min_z, double medial_sign,
                                 const HeelBisectorOptions& options, const std::string& source);

}  // namespace ergo
