// The shoe sole (paper §5.2, Fig. 7–8): a foot standing on a flat sole slab sized to it,
// loaded by half of a 75 kg adult's weight as an external force on the core plus an optional
// pitch torque for leaning (paper: "By tweaking this torque, we can simulate the effect of
// the human body leaning forwards or backwards"); the core translates vertically and
// pitches only (at a roll given or balanced once); the sole's top face is designed. Starts flat or
// from the negative image. Presets "quick" and "paper" (≥ 10k body vertices). SI units; y up, the
// foot along +z.
#pragma once

#include <optional>
#include <string>

#include "problems/foot_body.h"
#include "problems/negative_image.h"
#include "problems/roll_balance.h"
#include "problems/scenario.h"
#include "problems/scenario_parts.h"
#include "problems/stance_roll.h"

namespace ergo {

struct ShoeScenarioOptions {
  std::string preset = "quick";
  FootOptions foot;                // dimensions, depths, moduli, mass
  double body_edge_length = 0.01;  // target tet edge of the foot, m
  double sliver_bound_degrees = 10;
  // The sole: a slab whose top (y = 0) extends `sole_margin` beyond the foot's outline on
  // every side (0.28 × 0.12 m for the default foot), `sole_thickness` deep.
  double sole_thickness = 0.02, sole_margin = 0.01;  // m
  // The sole's outline: a rectangle, or the foot's footprint grown by sole_margin (a fitted
  // insole, problems/outline_sole.h; its STL prints as the insole).
  bool footprint_outline = false;
  // Edge lengths, m. The top matches the foot's skin edges (see ChairScenarioOptions::block:
  // measured on the quick shoe at 5 mm, the optimised φ was 68 % lower on the equilibrium the
  // optimiser followed but 80 % higher when the foot was placed afresh; at 10 mm 55 % / 52 %).
  double sole_top_spacing = 0.01, sole_wall_spacing = 0.01;
  double start_gap = 0.001;  // m
  // Load: load_fraction × body_mass × g downwards on the core (paper: half the body weight),
  // besides the foot's own weight; and lean_torque about +x (N·m; > 0 leans forward,
  // loading the toes; keep |torque| ≲ load × 8 cm so the centre of pressure stays on the sole).
  double body_mass = 75, load_fraction = 0.5, lean_torque = 0;
  // Where the load's line of action meets the sole, as a fraction of the foot's length from
  // the heel (quiet standing: the centre of pressure lies at 44.5 ± 5.5 % of the foot's
  // length, Teranishi et al. 2013); turned into a pitch torque on the core, added to
  // lean_torque. Unset: through the core's centre (the generated foot's centre of pressure is
  // then at 0.348 of its length; ergo's default for it before 2026-12-07).
  std::optional<double> load_point = 0.445;
  // The foot's roll about its length axis (z), held by the lock (a scan is not taken
  // standing): kGiven, `roll` (rad); kBalance, the roll at which it stands on the sole with no
  // torque about its length (problems/roll_balance.h); kStance, the roll that stands its heel
  // at `calcaneal_stance` (rad everted; problems/stance_roll.h); kAuto, kStance for a scanned
  // foot (a skin surface with the foot's anatomy, or a body directory built with it: a scan
  // at rest) and `roll` for the generated foot (modelled standing, its split already the
  // barefoot one: README "Scans").
  enum class RollRule { kGiven, kBalance, kStance, kAuto };
  RollRule roll_rule = RollRule::kAuto;
  double roll = 0;
  double calcaneal_stance = StanceRoll::kAdultCalcanealStance;
  RollBalanceOptions roll_balance;
  bool negative_image = false;
  NegativeImageOptions negative{0.01, 0, 3, 0.006, 10, 0.5, 0.001};
  std::string lock = "tx,tz,ry,rz";  // vertical translation and pitch (about x) only
  // Contact stiffness κ, Pa/m (mesh-independent), calibrated for 0.3 mm max penetration on
  // the quick preset's flat sole.
  double contact_stiffness = 1.4e9;
  double free_fall_mass_scale = 1e6;  // paper: 1e6 shoe
  // Filtered normal displacements, filter radius from the skin; the pressure smoothing has a
  // physical radius (12 mm: √3 × the quick preset's skin edge near the design), the same at
  // every resolution so that scores compare across meshes and presets.
  DesignSpaceOptions design_space{DesignParameterization::kFiltered, 0, 0.012};
  UserBodyInput user_body;
  UserSupportInput user_support;

  // "quick" or "paper"; throws InputError for anything else.
  static ShoeScenarioOptions FromPreset(const std::string& preset);
};

Scenario MakeShoeScenario(const ShoeScenarioOptions& options,
                          ScenarioBuildReport* report = nullptr);

}  // namespace ergo
