// Anatomical priors for a scanned body part (paper §3.1 measures tissue depth and stiffness on
// its subjects; a user with only a scan gets these instead of one constant): region-wise
// tissue depth and Young's modulus over the skin, from the part's axes and a few landmarks
// detected on it, as depth and modulus samples for the interpolation of
// sample_interpolation.h. The depth follows the bones' height where it matters (the foot's
// arch: its core is the bones' underside, well above the plantar skin), and the core is cut
// away where there are no bones (the toes are tissue).
// Measured samples (CSV) replace the priors near them. Every default and its source:
// ergo/body/README.md "Anatomical priors". Frames (ergo's convention; see axis_map.h):
//   foot  y up, the length along z (heel end detected, or given); the medial side detected
//         from the arch, or from the foot's side;
//   seat  y up, +z forward (towards the knees), the buttocks lowest;
//   hand  y up with the palm facing down, the fingers towards +z.
// Metres, Pa.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/heel_bisector.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

enum class Anatomy { kNone, kFoot, kSeat, kHand };
enum class HeelEnd { kAuto, kMinZ, kMaxZ };
enum class FootSide { kAuto, kLeft, kRight };

// "none", "foot", "seat", "hand"; "auto", "min_z", "max_z"; "auto", "left", "right".
// Throw InputError naming `flag` otherwise.
Anatomy ParseAnatomy(const std::string& text, const std::string& flag);
HeelEnd ParseHeelEnd(const std::string& text, const std::string& flag);
FootSide ParseFootSide(const std::string& text, const std::string& flag);
const char* AnatomyName(Anatomy anatomy);

struct AnatomyOptions {
  Anatomy anatomy = Anatomy::kNone;
  HeelEnd heel_end = HeelEnd::kAuto;
  FootSide foot_side = FootSide::kAuto;
  // Prior samples placed on the skin (farthest-point subset of its vertices).
  int samples = 200;
  // A measured sample replaces every prior sample within this distance of it, m.
  double override_radius = 0.02;
  // The priors' depth is raised to at least this, m: the mesher's edge length (a surface
  // body's layer must be one edge thick; the foot's dorsal 6 mm needs edges ≤ 6 mm). The
  // summary says when it raised anything.
  double min_depth = 0;
};

struct Landmark {
  std::string name;  // "heel", "ball", "medial arch", "toe tip", "ischial tuberosity (left)", ...
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // on the skin, m
  double depth = 0, youngs_modulus = 0;             // the prior there, m and Pa
  double stiffening_exponent = 2;                   // α there (2: neo-Hookean)
};

struct AnatomicalPriors {
  PointSamples depth;           // x,y,z,depth (m) on the skin
  PointSamples youngs_modulus;  // x,y,z,E (Pa) on the skin
  // x,y,z,α on the skin: the tissue's stiffening exponent (TissueMaterial), 2 where neo-Hookean.
  PointSamples stiffening_exponent;
  std::vector<Landmark> landmarks;
  // The part's extent along its length (foot: heel to toe tip; seat: back to knees; hand:
  // wrist to fingertips), m, and where it starts: the z of the heel / back / wrist end and
  // the direction of increasing length (+1 or −1 along z).
  double length = 0, start_z = 0, length_direction = 1;
  // Foot: how high its toes stand, m: the least height of the skin past the core's cut above
  // the weight-bearing line (through the heel's and the ball's lowest skin). A standing
  // foot's toes rest on the floor; a scan of a foot at rest lifts them (the FIND template:
  // 10.7 mm), and they then carry nothing (README "Scans"). Above 5 mm (a choice) the summary
  // says they are held up. 0 for the other anatomies.
  double toe_clearance = 0;
  // Foot: the heel's bisector as scanned (heel_bisector.h) with the foot's medial side; empty
  // when the heel's outline could not be bisected, and for the other anatomies. A scan of a
  // foot at rest stands its heel about upright (the FIND template: 0.91° everted), where
  // standing adults' heels stand about 6° everted (problems/stance_roll.h).
  std::optional<ScannedHeel> heel;
  std::string summary;  // one paragraph for people: the frame, the landmarks, the ranges
  // Where the part has no bones, the core is cut away: a signed implicit (m, positive
  // beyond the cut) for BuilderOptions::core_limit; empty for none. Foot: a plane across the
  // foot at the toe crease (the toes are tissue).
  std::function<double(const Eigen::Vector3d&)> core_limit;
};

// The priors of `options.anatomy` (not kNone) on `skin` (metres, in the anatomy's frame).
// Throws InputError naming `source` when the landmarks cannot be found (e.g. a foot whose
// heel end or medial side is ambiguous: give --heel_end / --foot_side).
AnatomicalPriors ComputeAnatomicalPriors(const TriMesh& skin, const AnatomyOptions& options,
                                         const std::string& source);

// Whether a foot's heel is at its smallest z (y up, the length along z): as `heel_end` says,
// or (kAuto) the end whose quarter of the foot reaches higher, the ankle. Throws InputError
// naming `source` when kAuto cannot tell.
bool HeelAtMinZ(const Vertices& foot, HeelEnd heel_end, const std::string& source);

// The prior samples with every one within `radius` of a measured sample removed, then the
// measured samples added (the measurement wins where it exists).
PointSamples OverridePriorSamples(const PointSamples& prior, const PointSamples& measured,
                                  double radius);

}  // namespace ergo
