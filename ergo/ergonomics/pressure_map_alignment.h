// The rigid motion of the plane that places a measured pressure map on the simulated one,
// both seen along the load (y up): a plate's frame, and where the person stood, differ from
// the simulation's. It maximises the overlap of the two maps over the simulated footprint,
// sampled on a grid of pitch h, scored by either
//   footprint: the Dice overlap 2 Σ a b / (Σ a + Σ b) of soft footprints a, b = min(1, p/p_t)
//              (1 where the pressure exceeds the footprint threshold p_t, ramping to 0 at no
//              pressure, so the score is continuous in the motion), or
//   pressure:  the cosine similarity Σ a b / √(Σ a² Σ b²) of the pressures themselves,
// where Σ b and Σ b² are the measured map's own sums (taken once in its frame, so pushing
// measured load off the simulated footprint never raises the score). The search needs no
// first guess of the orientation (a plate export may lie at any angle, and a footprint's
// principal axis is ambiguous by 180°): every 10° of the full circle with the centres of
// pressure matched, then a pattern search on (θ, shift) from the three best, rotating about
// the measured centre of pressure, its steps halved from (4°, 4 mm) down to (0.005°,
// 0.005 mm). Metres, radians, Pa.
#pragma once

#include <string>

#include "ergo/ergonomics/planar_pressure_map.h"
#include "ergo/ergonomics/rigid_motion_2d.h"

namespace ergo {

enum class AlignmentMode { kNone, kTranslation, kRigid };
enum class AlignmentScore { kFootprint, kPressure };

// "none", "translation", "rigid"; "footprint", "pressure"; and back (false for other words).
const char* AlignmentModeName(AlignmentMode mode);
bool ParseAlignmentMode(const std::string& name, AlignmentMode* mode);
const char* AlignmentScoreName(AlignmentScore score);
bool ParseAlignmentScore(const std::string& name, AlignmentScore* score);

struct AlignmentOptions {
  AlignmentMode mode = AlignmentMode::kRigid;
  AlignmentScore score = AlignmentScore::kFootprint;
  double footprint_threshold = 0;  // p_t, Pa, > 0
  double grid_pitch = 0.002;       // h, m
};

struct PressureMapAlignment {
  RigidMotion2d motion;      // measured map's frame → simulated map's frame
  double initial_score = 0;  // the score with the measured map where it was
  double score = 0;          // at `motion`
  int evaluations = 0;
  // "rigid by footprint: rotated 8.02° and shifted (12.1, -7.0) mm about the measured
  // centre of pressure; score 0.71 -> 0.98 (412 evaluations)".
  std::string Describe(const PlanarPressureMap& measured) const;
};

PressureMapAlignment AlignPressureMaps(const PlanarPressureMap& simulated,
                                       const PlanarPressureMap& measured,
                                       const AlignmentOptions& options);

// The force-weighted centroid of a map's samples (its centre of pressure), m.
Eigen::Vector2d PressureCentroid(const PlanarPressureMap& map);

}  // namespace ergo
