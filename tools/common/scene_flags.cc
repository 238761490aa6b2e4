#include "tools/common/scene_flags.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <gflags/gflags.h>

#include "ergo/mesh/input_error.h"
#include "problems/chair_scenario.h"
#include "problems/mouse_scenario.h"
#include "problems/shoe_scenario.h"
#include "tools/common/flag_checks.h"

// Shared by the three scenes.
DEFINE_string(preset, "quick",
              "chair/shoe/mouse resolution: quick (an optimisation in about a minute) or paper "
              "(>= 10k body vertices; chair >= 25k support vertices)");
DEFINE_bool(negative_image, false,
            "start from the negative image: the support minus the body pushed in by "
            "--negative_image_depth (CGAL corefinement, rim smoothed)");
DEFINE_double(negative_image_depth, -1,
              "how far the body is pushed into the support for the negative image, m; negative = "
              "the scene's default (chair 0.05, shoe 0.01, mouse 0.005)");
DEFINE_double(body_edge_length, 0, "target tet edge length of the generated body, m; 0 = preset");
DEFINE_double(support_edge_length, 0,
              "edge length of the designed support surface (chair/sole top spacing, mouse edge), "
              "m; 0 = preset");
DEFINE_double(start_gap, -1, "the body starts this far above the support, m; negative = scene's");
DEFINE_string(lock, "",
              "core DOFs held fixed, e.g. tx,tz (chair), tx,tz,ry,rz (shoe); empty = the scene's");
DEFINE_string(parameterization, "filtered",
              "design variables: filtered (one per designed vertex, moving the surface along its "
              "normals through a Helmholtz filter of radius --filter_radius: mesh-independent), "
              "spline (the control values of a cubic B-spline lattice in space of knot spacing "
              "--filter_radius, sampled at the designed vertices: the same variables on every "
              "mesh of the support), normal (the raw displacement along the initial normal per "
              "designed vertex) or "
              "positions (three raw coordinates per designed vertex)");
DEFINE_string(filter_radius, "auto",
              "radius r of the design filter (the knot spacing of --parameterization=spline), m, "
              "or auto (2.5 × the skin's mean edge near the designed region)");
DEFINE_string(pressure_smoothing_radius, "scene",
              "radius of the Helmholtz smoothing of the pressures before scoring, m; scene (the "
              "scene's physical radius, the same at every resolution: shoe 12 mm, chair 44 mm, "
              "mouse 9 mm), skin (√3 × the skin's mean edge near the designed region: the "
              "paper's one-ring reach on this skin) or umbrella (the paper's umbrella Laplacian)");
// A user's body instead of the generated one.
DEFINE_string(body_dir, "", "a body directory written by `ergo_body build` (replaces the body)");
DEFINE_string(tet_mesh, "",
              "a tet mesh of the tissue layer (.msh, .node/.ele; replaces the body): outer "
              "boundary = skin, inner boundary = the core's surface; units --skin_unit, E from "
              "--stiffness_csv or --skin_youngs_modulus");
DEFINE_string(skin, "",
              "a skin surface (.obj .off .ply .stl .msh) meshed into a tissue layer (replaces "
              "the body)");
DEFINE_string(skin_unit, "m", "unit of --skin, --depth_csv and --stiffness_csv: m or mm");
DEFINE_string(depth_csv, "", "x,y,z,depth samples of the tissue depth for --skin");
DEFINE_string(stiffness_csv, "", "x,y,z,E samples of Young's modulus (Pa) for --skin");
DEFINE_string(anatomy, "none",
              "--skin: anatomical priors for the tissue depth and E (foot, seat, hand or none; "
              "ergo/body/README.md); --depth_csv / --stiffness_csv replace them near their points "
              "and --skin_depth / --skin_youngs_modulus are then unused");
DEFINE_string(skin_axes, "x,y,z",
              "--skin: the scan's axes that become ergo's x, y (up) and z (the part's length), "
              "e.g. y,z,x for a scan with z up and its length along x");
DEFINE_string(heel_end, "auto",
              "a user's foot (--anatomy=foot, --shoe_load_point): auto (the end with the ankle), "
              "min_z or max_z");
DEFINE_string(foot_side, "auto", "--anatomy=foot: left, right or auto (from the arch)");
DEFINE_double(skin_depth, 0.02, "constant tissue depth for --skin without --depth_csv, m");
DEFINE_double(skin_youngs_modulus, 1e4, "constant E for --skin without --stiffness_csv, Pa");
DEFINE_double(skin_poisson_ratio, 0.45, "Poisson's ratio of --skin's tissue");
DEFINE_double(skin_total_mass, -1,
              "total mass of --skin's body part, kg; negative = core volume x "
              "1050 kg/m^3");
// A user's support instead of the generated one.
DEFINE_string(support_mesh, "", "a closed support surface (.obj .off .ply .stl .msh)");
DEFINE_string(support_unit, "m", "unit of --support_mesh: m or mm");
DEFINE_string(designed, "up",
              "which vertices of --support_mesh are designed: up (normal's y above "
              "--designed_min_normal_y) or all");
DEFINE_double(designed_min_normal_y, 0.5, "see --designed");
// Scene-specific.
DEFINE_double(chair_upper_body_load, 0, "chair: extra downward force on the core, N (paper: 0)");
DEFINE_string(chair_load_point, "none",
              "chair: where the whole load's line meets the seat, as a fraction of the seat's "
              "depth from the back (a pitch torque on the core), or none (the weight acts at the "
              "body's centre of mass)");
DEFINE_double(chair_front_radius, 0.06, "chair: radius of the arc under the knees, m");
DEFINE_double(chair_body_mass, 30, "chair: mass of the seated body part, kg");
DEFINE_double(shoe_lean_torque, 0,
              "shoe: torque about x on the foot's core, N m (> 0 leans forward onto the toes)");
DEFINE_string(shoe_load_point, "0.445",
              "shoe: where the load's line meets the sole, as a fraction of the foot's length "
              "from the heel (quiet standing: 0.445, Teranishi et al. 2013); none: through the "
              "core's centre (the generated foot's default before 2026-12-07)");
DEFINE_string(shoe_roll, "auto",
              "shoe: the foot's roll about its length in degrees (> 0 turns +x up), held while "
              "standing; or balance: the roll at which the load through the core's centre "
              "leaves no torque about the length, found by a few equilibria on the sole; or "
              "stance: the roll that stands the heel's bisector at --shoe_calcaneal_stance; or "
              "auto: stance for a scanned foot (--anatomy=foot), 0 for the generated foot");
DEFINE_double(shoe_calcaneal_stance, 6.07,
              "shoe, with --shoe_roll=stance: the wearer's resting calcaneal stance position, "
              "degrees everted (< 0 inverted); default the healthy adults' mean, 6.07 +- 2.7 "
              "(Sobel et al. 1999)");
DEFINE_string(shoe_sole_outline, "rectangle",
              "shoe: the sole's outline: rectangle, or footprint (the foot's footprint grown by "
              "--shoe_sole_margin: a fitted insole, printed as such)");
DEFINE_double(shoe_sole_margin, 0.01, "shoe: the sole's outline beyond the foot's, m");
DEFINE_double(shoe_body_mass, 75, "shoe: the wearer's mass, kg");
DEFINE_double(shoe_load_fraction, 0.5, "shoe: fraction of the wearer's weight on this foot");
DEFINE_double(shoe_foot_length, 0.26,
              "shoe: the generated foot's length, heel to longest toe, m (adults 0.23-0.29; the "
              "sole is sized to the foot)");
DEFINE_double(shoe_foot_breadth_scale, 1,
              "shoe: the generated foot's breadth and height relative to a 0.26 m foot's");
DEFINE_double(shoe_modulus_scale, 1,
              "shoe: every region's tissue Young's modulus times this (a stiffer or softer foot)");
DEFINE_double(mouse_hand_mass, 0.45, "mouse: mass of the hand, kg");

namespace ergo {
namespace {

LengthUnit UnitFlag(const std::string& text, const char* flag) {
  LengthUnit unit;
  if (!ParseLengthUnit(text, &unit))
    throw InputError(std::string("--") + flag, "", "'" + text + "' is not a unit", "use m or mm");
  return unit;
}

// A positive length in metres from a flag, or `fallback` for the flag's word (auto, ...).
double LengthFlag(const std::string& text, const char* flag, const char* word, double fallback) {
  if (text == word) return fallback;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || !(value > 0) || value > 10) {
    throw InputError(std::string("--") + flag, "", "'" + text + "' is not a length in metres",
                     std::string("give e.g. 0.02 (m) or ") + word);
  }
  return value;
}

// The spline space's smallest knot spacing, m (DesignSpaceFlags).
constexpr double kMinimumKnotSpacing = 1e-3;

// The scene's design space with the flags' changes.
DesignSpaceOptions DesignSpaceFlags(DesignSpaceOptions space) {
  if (FLAGS_parameterization == "filtered") {
    space.parameterization = DesignParameterization::kFiltered;
  } else if (FLAGS_parameterization == "spline") {
    space.parameterization = DesignParameterization::kSpline;
  } else if (FLAGS_parameterization == "normal") {
    space.parameterization = DesignParameterization::kNormalDisplacement;
  } else if (FLAGS_parameterization == "positions") {
    space.parameterization = DesignParameterization::kPositions;
  } else {
    throw InputError("--parameterization", "", "'" + FLAGS_parameterization + "' is unknown",
                     "use filtered, spline, normal or positions");
  }
  space.filter_radius = LengthFlag(FLAGS_filter_radius, "filter_radius", "auto", 0);
  // auto is 0 here (2.5 skin edges, set by the scene).
  if (space.parameterization == DesignParameterization::kSpline && space.filter_radius > 0 &&
      space.filter_radius < kMinimumKnotSpacing) {
    throw InputError("--filter_radius", "",
                     "a spline knot spacing of " + FLAGS_filter_radius +
                         " m is below 1 mm: finer than any support ergo meshes, with up to 64 "
                         "controls per designed vertex",
                     "give at least 0.001 (m), e.g. 0.018, or auto");
  }
  if (FLAGS_pressure_smoothing_radius == "umbrella") {
    space.pressure_smoothing_radius = 0;
  } else if (FLAGS_pressure_smoothing_radius != "scene") {
    space.pressure_smoothing_radius =
        LengthFlag(FLAGS_pressure_smoothing_radius, "pressure_smoothing_radius", "skin", -1);
  }
  return space;
}

UserBodyInput UserBodyFlags() {
  UserBodyInput input;
  if (!FLAGS_body_dir.empty() + !FLAGS_tet_mesh.empty() + !FLAGS_skin.empty() > 1) {
    throw InputError("--body_dir", "", "more than one of --body_dir, --tet_mesh, --skin is given",
                     "give one of them");
  }
  input.body_directory = FLAGS_body_dir;
  input.tet_mesh = FLAGS_tet_mesh;
  input.skin_surface = FLAGS_skin;
  input.unit = UnitFlag(FLAGS_skin_unit, "skin_unit");
  input.depth_csv = FLAGS_depth_csv;
  input.stiffness_csv = FLAGS_stiffness_csv;
  input.depth = FLAGS_skin_depth;
  input.youngs_modulus = FLAGS_skin_youngs_modulus;
  input.poisson_ratio = FLAGS_skin_poisson_ratio;
  input.total_mass = FLAGS_skin_total_mass;
  input.anatomy.anatomy = ParseAnatomy(FLAGS_anatomy, "--anatomy");
  input.anatomy.heel_end = ParseHeelEnd(FLAGS_heel_end, "--heel_end");
  input.anatomy.foot_side = ParseFootSide(FLAGS_foot_side, "--foot_side");
  input.axes = FLAGS_skin_axes;
  if ((input.anatomy.anatomy != Anatomy::kNone || input.axes != "x,y,z") && FLAGS_skin.empty()) {
    throw InputError(input.anatomy.anatomy != Anatomy::kNone ? "--anatomy" : "--skin_axes", "",
                     "applies to a scanned skin surface only", "give --skin=FILE or drop it");
  }
  return input;
}

UserSupportInput UserSupportFlags() {
  UserSupportInput input;
  input.path = FLAGS_support_mesh;
  input.unit = UnitFlag(FLAGS_support_unit, "support_unit");
  if (FLAGS_designed == "up") {
    input.active = ActiveRule::kUpwardFacing;
  } else if (FLAGS_designed == "all") {
    input.active = ActiveRule::kAll;
  } else {
    throw InputError("--designed", "", "'" + FLAGS_designed + "' is unknown", "use up or all");
  }
  input.min_normal_y = FLAGS_designed_min_normal_y;
  return input;
}

// Every scene flag checked at once, before anything is built: finite, in range, and not
// asking for meshes that would not fit in memory.
void ValidateSceneFlags() {
  auto optional_length = [](const char* flag, double value, double high, const char* fix) {
    // Negative or 0 = the preset's; otherwise a finite length up to `high`.
    if (std::isnan(value) || (value > 0 && !(value <= high)))
      RequireInRange(flag, value, 0, high, fix);
  };
  optional_length("negative_image_depth", FLAGS_negative_image_depth, 0.2, "metres, e.g. 0.05");
  optional_length("start_gap", FLAGS_start_gap, 0.1, "metres, e.g. 0.001");
  RequireInRange("body_edge_length", FLAGS_body_edge_length, 0, 0.5,
                 "metres, e.g. 0.01; 0 = the preset's");
  RequireInRange("support_edge_length", FLAGS_support_edge_length, 0, 0.5,
                 "metres, e.g. 0.005; 0 = the preset's");
  // Meshes beyond a few million elements do not fit this machine's memory or time: the body
  // builder refuses those itself; the designed support surface is estimated here (its
  // largest top, the chair's 0.5 m x 0.5 m, at the requested spacing).
  if (FLAGS_support_edge_length > 0) {
    const double vertices = (0.5 / FLAGS_support_edge_length) * (0.5 / FLAGS_support_edge_length);
    if (vertices > 2e6) {
      std::ostringstream what;
      what << "would make a support of about " << std::scientific << std::setprecision(2)
           << vertices << " vertices (over 2e6; roughly " << vertices * 2e-6
           << " GB for its trees and the design's operators)";
      throw InputError("--support_edge_length", "", what.str(),
                       "use a spacing of 0.5 mm or more, e.g. 0.0025");
    }
  }
  if (FLAGS_body_edge_length > 0 && FLAGS_body_edge_length < 1e-3) {
    throw InputError("--body_edge_length", "",
                     "is below 1 mm: the generated bodies would have over 1e8 tets",
                     "use 0.003 or more (the paper presets use 0.006–0.019)");
  }
  RequireInRange("skin_depth", FLAGS_skin_depth, 1e-4, 0.2, "metres, e.g. 0.02");
  RequireInRange("skin_youngs_modulus", FLAGS_skin_youngs_modulus, 1, 1e9, "Pa, e.g. 1e4");
  RequireInRange("skin_poisson_ratio", FLAGS_skin_poisson_ratio, -0.99, 0.4999, "e.g. 0.45");
  if (std::isnan(FLAGS_skin_total_mass) || FLAGS_skin_total_mass > 1e4)
    RequireInRange("skin_total_mass", FLAGS_skin_total_mass, -1e9, 1e4,
                   "kg; negative = from volume");
  RequireInRange("designed_min_normal_y", FLAGS_designed_min_normal_y, -1, 1, "e.g. 0.5");
  RequireInRange("chair_upper_body_load", FLAGS_chair_upper_body_load, 0, 1e4, "N, e.g. 0");
  RequireInRange("chair_front_radius", FLAGS_chair_front_radius, 0, 0.2, "metres, e.g. 0.06");
  RequireInRange("chair_body_mass", FLAGS_chair_body_mass, 1, 500, "kg, e.g. 30");
  RequireInRange("shoe_lean_torque", FLAGS_shoe_lean_torque, -1e3, 1e3, "N m, e.g. 0");
  RequireInRange("shoe_body_mass", FLAGS_shoe_body_mass, 1, 500, "kg, e.g. 75");
  RequireInRange("shoe_sole_margin", FLAGS_shoe_sole_margin, 0, 0.1, "metres, e.g. 0.01");
  RequireInRange("shoe_load_fraction", FLAGS_shoe_load_fraction, 0, 1, "e.g. 0.5");
  RequireInRange("shoe_foot_length", FLAGS_shoe_foot_length, 0.185, 0.335, "metres, e.g. 0.26");
  RequireInRange("shoe_foot_breadth_scale", FLAGS_shoe_foot_breadth_scale, 0.65, 1.55, "e.g. 1");
  RequireInRange("shoe_modulus_scale", FLAGS_shoe_modulus_scale, 0.05, 20, "e.g. 1.3");
  RequireInRange("mouse_hand_mass", FLAGS_mouse_hand_mass, 0.01, 10, "kg, e.g. 0.45");
}

// A fraction in [0, 1] from a flag, or nullopt for its `word` (none, auto).
std::optional<double> FractionFlag(const std::string& text, const char* flag, const char* word) {
  if (text == word) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(value >= 0 && value <= 1)) {
    throw InputError(std::string("--") + flag, "", "'" + text + "' is not a fraction in [0, 1]",
                     std::string("give e.g. 0.445, or ") + word);
  }
  return value;
}

// --shoe_load_point: a fraction in [0, 1], or none (through the core's centre); auto, which
// flagfiles written before 2026-12-07 may carry, is quiet standing's 0.445 as for every foot.
std::optional<double> ShoeLoadPointFlag() {
  if (FLAGS_shoe_load_point == "auto") return 0.445;
  return FractionFlag(FLAGS_shoe_load_point, "shoe_load_point", "none");
}

// --shoe_roll: an angle in degrees, balance, stance (with --shoe_calcaneal_stance) or auto.
void ApplyShoeRollFlag(ShoeScenarioOptions* o) {
  const std::string& text = FLAGS_shoe_roll;
  using RollRule = ShoeScenarioOptions::RollRule;
  RequireInRange("shoe_calcaneal_stance", FLAGS_shoe_calcaneal_stance, -30, 30,
                 "the resting calcaneal stance position in degrees everted, e.g. 6.07");
  o->calcaneal_stance = FLAGS_shoe_calcaneal_stance * RollBalanceOptions::kDegree;
  if (text != "stance" && text != "auto" &&
      !gflags::GetCommandLineFlagInfoOrDie("shoe_calcaneal_stance").is_default) {
    throw InputError("--shoe_calcaneal_stance", "",
                     "a stance is only stood with --shoe_roll=stance or auto, not " + text,
                     "drop one of the two flags");
  }
  if (text == "balance") {
    o->roll_rule = RollRule::kBalance;
    o->roll_balance.progress = [](const std::string& line) { std::cout << "  " << line << "\n"; };
    return;
  }
  if (text == "stance" || text == "auto") {
    o->roll_rule = text == "stance" ? RollRule::kStance : RollRule::kAuto;
    o->roll = 0;
    return;
  }
  o->roll_rule = RollRule::kGiven;
  char* end = nullptr;
  const double degrees = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(std::abs(degrees) <= 30)) {
    throw InputError("--shoe_roll", "", "'" + text + "' is not an angle within ±30 degrees",
                     "give e.g. 0 or 11.5, balance, stance or auto");
  }
  o->roll = degrees * RollBalanceOptions::kDegree;
}

// The flags every scene shares, applied to its options struct.
template <typename Options>
void ApplyCommonFlags(Options* o) {
  ValidateSceneFlags();
  o->negative_image = FLAGS_negative_image;
  if (FLAGS_negative_image_depth >= 0) o->negative.depth = FLAGS_negative_image_depth;
  if (FLAGS_body_edge_length < 0)
    throw InputError("--body_edge_length", "", "must not be negative", "0 keeps the preset's");
  if (FLAGS_body_edge_length > 0) o->body_edge_length = FLAGS_body_edge_length;
  if (FLAGS_support_edge_length < 0)
    throw InputError("--support_edge_length", "", "must not be negative", "0 keeps the preset's");
  if (FLAGS_start_gap >= 0) o->start_gap = FLAGS_start_gap;
  if (!FLAGS_lock.empty()) o->lock = FLAGS_lock;
  o->design_space = DesignSpaceFlags(o->design_space);
  o->user_body = UserBodyFlags();
  o->user_support = UserSupportFlags();
}

// The preset's κ (Pa/m, independent of the mesh spacing) was calibrated for the generated
// body and support: say so when the user brings their own.
void WarnIfStiffnessUncalibrated(const char* scene) {
  std::string stiffness;  // --contact_stiffness lives with the design flags
  if (gflags::GetCommandLineOption("contact_stiffness", &stiffness) && stiffness != "scenario")
    return;
  if (!FLAGS_body_dir.empty() || !FLAGS_tet_mesh.empty() || !FLAGS_skin.empty() ||
      !FLAGS_support_mesh.empty()) {
    std::cerr << "note: " << scene
              << ": the preset's contact stiffness κ was calibrated for the generated body and "
                 "support (0.3 mm largest penetration); for your own, consider "
                 "--contact_stiffness=auto\n";
  }
}

void PrintReport(const ScenarioBuildReport& r) {
  std::cout << "  " << r.body << "\n  " << r.support << "\n";
  if (!r.roll.empty()) std::cout << "  roll: " << r.roll << "\n";
  if (!r.negative_image.empty()) std::cout << "  negative image: " << r.negative_image << "\n";
  std::cout << "  built in "
            << r.body_seconds + r.support_seconds + r.negative_image_seconds + r.start_seconds
            << " s\n";
}

// Builds the scene, printing its build report (and the stiffness note where it applies).
template <typename Options>
Scenario BuildAndReport(const char* scene, const Options& options,
                        Scenario (*make)(const Options&, ScenarioBuildReport*)) {
  WarnIfStiffnessUncalibrated(scene);
  ScenarioBuildReport report;
  Scenario scenario = make(options, &report);
  PrintReport(report);
  return scenario;
}

}  // namespace

Scenario MakeChairFromFlags() {
  ChairScenarioOptions o = ChairScenarioOptions::FromPreset(FLAGS_preset);
  ApplyCommonFlags(&o);
  if (FLAGS_support_edge_length > 0) o.block.top_spacing = FLAGS_support_edge_length;
  o.block.wall_spacing = std::max(o.block.wall_spacing, o.block.top_spacing);
  o.upper_body_load = FLAGS_chair_upper_body_load;
  o.load_point = FractionFlag(FLAGS_chair_load_point, "chair_load_point", "none");
  o.block.front_radius = FLAGS_chair_front_radius;
  o.body.total_mass = FLAGS_chair_body_mass;
  return BuildAndReport("chair", o, MakeChairScenario);
}

Scenario MakeShoeFromFlags() {
  ShoeScenarioOptions o = ShoeScenarioOptions::FromPreset(FLAGS_preset);
  ApplyCommonFlags(&o);
  if (FLAGS_support_edge_length > 0) {
    o.sole_top_spacing = FLAGS_support_edge_length;
    o.sole_wall_spacing = std::max(o.sole_wall_spacing, o.sole_top_spacing);
  }
  o.lean_torque = FLAGS_shoe_lean_torque;
  o.load_point = ShoeLoadPointFlag();
  ApplyShoeRollFlag(&o);
  if (FLAGS_shoe_sole_outline != "rectangle" && FLAGS_shoe_sole_outline != "footprint") {
    throw InputError("--shoe_sole_outline", "", "'" + FLAGS_shoe_sole_outline + "' is unknown",
                     "use rectangle or footprint");
  }
  o.footprint_outline = FLAGS_shoe_sole_outline == "footprint";
  o.sole_margin = FLAGS_shoe_sole_margin;
  o.body_mass = FLAGS_shoe_body_mass;
  o.load_fraction = FLAGS_shoe_load_fraction;
  o.foot.length = FLAGS_shoe_foot_length;
  o.foot.breadth_scale = FLAGS_shoe_foot_breadth_scale;
  for (double* modulus : {&o.foot.heel_modulus, &o.foot.arch_modulus, &o.foot.ball_modulus,
                          &o.foot.toe_modulus, &o.foot.dorsal_modulus})
    *modulus *= FLAGS_shoe_modulus_scale;
  return BuildAndReport("shoe", o, MakeShoeScenario);
}

Scenario MakeMouseFromFlags() {
  MouseScenarioOptions o = MouseScenarioOptions::FromPreset(FLAGS_preset);
  ApplyCommonFlags(&o);
  if (FLAGS_support_edge_length > 0) o.mouse.edge_length = FLAGS_support_edge_length;
  o.hand.total_mass = FLAGS_mouse_hand_mass;
  return BuildAndReport("mouse", o, MakeMouseScenario);
}

}  // namespace ergo
