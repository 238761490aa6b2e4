// The roll a foot stands at, from its heel. A scan is taken of a foot at rest, its heel about
// upright (the FIND template's bisector: 0.9° everted); standing, an adult's heel is everted
// by the subtalar joint's pronation (resting calcaneal stance position, RCSP: 6.07 ± 2.7° in
// healthy adults, Sobel et al. 1999; a calcaneal stance in 7° of valgus on average, with a
// forefoot in 6° of varus, in 121 healthy adults, Åström & Arvidson 1995, J Orthop Sports
// Phys Ther 22:216). ergo's foot has one rigid core, so the whole foot turns: the stance roll
// is the turn about the length that brings the heel's bisector, drawn on the skin as scanned
// (ergo/body/heel_bisector.h), to the stance's eversion. A clinician's measured RCSP replaces
// the population's mean. y up, the foot's length along z; rad.
#pragma once

#include <string>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/heel_bisector.h"
#include "ergo/body/layered_body.h"

namespace ergo {

struct StanceRoll {
  static constexpr double kDegree = 3.14159265358979323846 / 180;
  static constexpr double kAdultCalcanealStance = 6.07 * kDegree;  // Sobel et al. 1999's mean

  double roll = 0;              // rad about +z (> 0 turns +x up), as RolledRestState takes it
  double heel_eversion = 0;     // the heel's bisector at rest, rad (> 0 everted)
  double calcaneal_stance = 0;  // the eversion it stands at, rad
  double medial_sign = 0;       // +1: the medial side is +x
  std::string measured_on;      // where the heel was bisected: "the scan", "the body's skin"
  std::string BriefReport() const;
};

// The roll that stands `heel` (its bisector at rest, bisected on `measured_on`) at
// `calcaneal_stance` (rad everted): medial_sign · (eversion − calcaneal_stance). Throws
// InputError naming `source` for a non-finite angle, a side neither +1 nor −1, or a roll beyond
// `max_roll`.
StanceRoll StanceRollFrom(const ScannedHeel& heel, double calcaneal_stance, double max_roll,
                          const std::string& measured_on, const std::string& source);

// The same, the heel bisected on `body`'s rest skin read as a foot (`anatomy`: its heel end
// and side; auto detects them as `ergo_body build --anatomy=foot` does). Throws InputError
// naming `source` when the skin is not a foot whose heel and medial side can be told, or the
// roll would exceed `max_roll`. A scan's own bisector, measured on the scan as read before
// meshing (ScenarioBuildReport, RecordedAnatomy), is preferred where there is one: the meshed
// skins' differ from it by up to 0.8° with the edge length (their heels' facets).
StanceRoll FindStanceRoll(const LayeredBody& body, const AnatomyOptions& anatomy,
                          double calcaneal_stance, double max_roll, const std::string& source);

}  // namespace ergo
