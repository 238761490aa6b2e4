#include "problems/shoe_scenario.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/core_lock.h"
#include "ergo/design/lengthwise_shares.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"
#include "problems/load_point.h"
#include "problems/outline_sole.h"
#include "problems/profile_block.h"

namespace ergo {
ShoeScenarioOptions ShoeScenarioOptions::FromPreset(const std::string& preset) {
  ShoeScenarioOptions o;
  o.preset = preset;
  if (preset == "quick") return o;
  if (preset == "paper") {
    o.body_edge_length = 0.006;
    o.sliver_bound_degrees = 12;
    o.sole_top_spacing = 0.005;
    o.sole_wall_spacing = 0.005;
    return o;
  }
  throw InputError("shoe scenario", "preset", "unknown preset \"" + preset + "\"",
                   "use quick or paper");
}

Scenario MakeShoeScenario(const ShoeScenarioOptions& o, ScenarioBuildReport* report) {
  ScenarioBuildReport local;
  ScenarioBuildReport& r = report != nullptr ? *report : local;
  if (!(o.body_edge_length > 0) || !(o.contact_stiffness > 0) || !(o.free_fall_mass_scale > 0) ||
      !(o.start_gap >= 0) || !(o.body_mass >= 0) || !(o.load_fraction >= 0) ||
      !(o.sole_thickness > 0) || !(o.sole_margin >= 0) || !std::isfinite(o.lean_torque) ||
      !(std::abs(o.roll) <= o.roll_balance.max_roll) ||
      (o.load_point && !(*o.load_point >= 0 && *o.load_point <= 1))) {
    throw InputError("shoe scenario", "options",
                     "edge length, stiffness, free-fall scale and sole thickness must be "
                     "positive; gap, margin, body mass and load fraction non-negative; the "
                     "torque finite; the load point in [0, 1]; the roll within the largest "
                     "roll (30 degrees)",
                     "check the shoe options");
  }
  Scenario scenario;
  scenario.name = "shoe";
  LayeredBodyOptions load;
  load.lock = ParseCoreLock(o.lock, "shoe lock");
  load.external_force = Eigen::Vector3d(0, -o.load_fraction * o.body_mass * 9.81, 0);
  load.external_torque = Eigen::Vector3d(o.lean_torque, 0, 0);

  scenario.body = MakeScenarioBody(
      "foot", [&] { return MakeFootSpec(o.foot); }, o.body_edge_length, o.sliver_bound_degrees,
      o.user_body, load, &r);
  if (o.load_point) {
    const Eigen::Vector3d torque =
        load.external_torque +
        LoadPointTorque(*scenario.body, load.external_force, *o.load_point,
                        o.user_body.empty() ? HeelEnd::kMinZ : o.user_body.anatomy.heel_end,
                        "shoe load point");
    auto loaded = std::make_shared<LayeredBody>(*scenario.body);
    loaded->SetExternalWrench(load.external_force, torque);
    scenario.body = loaded;
  }

  // The sole: the standing foot's outline (x, z) grown by the margin, top at y = 0. The foot
  // stands at its roll, so the outline is the rest shape's turned by it.
  const bool generated_sole = o.user_support.empty();
  ProfileBlock sole;
  double shift_x = 0;
  std::vector<bool> outline_top;
  auto make_sole = [&](double roll) {
    const auto begin = std::chrono::steady_clock::now();
    const LayeredBody& body = *scenario.body;
    const Vertices standing =
        roll == 0 ? body.rest().vertices : DeformedPositions(body, RolledRestState(body, roll));
    if (generated_sole && o.footprint_outline) {
      OutlineSoleOptions outline;
      outline.margin = o.sole_margin;
      outline.thickness = o.sole_thickness;
      outline.top_spacing = o.sole_top_spacing;
      outline.wall_spacing = std::max(o.sole_wall_spacing, o.sole_top_spacing);
      OutlineSole fitted = MakeOutlineSole(body.skin().RestSurface(standing), outline);
      scenario.support = std::move(fitted.mesh);
      outline_top = std::move(fitted.top);
    } else if (generated_sole) {
      const Eigen::RowVector3d lo = standing.colwise().minCoeff(),
                               hi = standing.colwise().maxCoeff();
      shift_x = 0.5 * (lo.x() + hi.x());
      sole = ProfileBlock{hi.x() - lo.x() + 2 * o.sole_margin,
                          lo.z() - o.sole_margin,
                          hi.z() + o.sole_margin,
                          -o.sole_thickness,
                          0,
                          0,
                          o.sole_top_spacing,
                          o.sole_wall_spacing};
      scenario.support = MakeProfileBlock(sole);
      scenario.support.vertices.col(0).array() += shift_x;
    } else {
      scenario.support = LoadUserSupport(o.user_support);
    }
    r.support_seconds += SecondsSince(begin);
  };
  using RollRule = ShoeScenarioOptions::RollRule;
  const bool balance_roll = o.roll_rule == RollRule::kBalance;
  const bool stance_roll =
      o.roll_rule == RollRule::kStance || (o.roll_rule == RollRule::kAuto && r.scanned_foot);
  double roll = o.roll;
  if (stance_roll) {
    // The heel bisected on the scan as read where it was; else on the body's skin.
    AnatomyOptions anatomy = o.user_body.anatomy;
    if (o.user_body.empty()) anatomy.heel_end = HeelEnd::kMinZ;
    const StanceRoll stance =
        r.scanned_heel ? StanceRollFrom(*r.scanned_heel, o.calcaneal_stance,
                                        o.roll_balance.max_roll, "the scan", "shoe stance roll")
                       : FindStanceRoll(*scenario.body, anatomy, o.calcaneal_stance,
                                        o.roll_balance.max_roll, "shoe stance roll");
    roll = stance.roll;
    r.roll = stance.BriefReport();
  }
  make_sole(balance_roll ? 0 : roll);
  const double support_seconds = r.support_seconds;
  auto start = std::chrono::steady_clock::now();
  if (balance_roll) {
    EquilibriumOptions equilibrium = scenario.design.equilibrium;
    equilibrium.contact_stiffness = o.contact_stiffness;
    equilibrium.free_fall_mass_scale = o.free_fall_mass_scale;
    const RollBalance balance = BalanceRoll(*scenario.body, scenario.support, o.start_gap,
                                            equilibrium, o.roll_balance, "shoe");
    r.roll = balance.BriefReport();
    r.roll_radians = balance.roll;
    scenario.start = balance.start;
    if (generated_sole && balance.roll != 0) {
      // Balanced on the level foot's sole; the sole is then cut under the standing foot.
      make_sole(balance.roll);
      scenario.start = StartAbove(*scenario.body, RolledRestState(*scenario.body, balance.roll),
                                  scenario.support, o.start_gap, "shoe");
    }
  } else {
    scenario.start = StartAbove(*scenario.body, RolledRestState(*scenario.body, roll),
                                scenario.support, o.start_gap, "shoe");
    r.roll_radians = roll;
  }
  scenario.design.placement_gap = o.start_gap;
  r.start_seconds = SecondsSince(start) - (r.support_seconds - support_seconds);
  if (o.negative_image) {
    if (generated_sole && !(o.negative.depth < o.sole_thickness - 0.002)) {
      throw InputError("shoe scenario", "negative image depth",
                       "the foot would be pushed through the sole",
                       "use a depth at least 2 mm below the sole thickness");
    }
    UseNegativeImage(o.negative, o.start_gap, &scenario, &r);
  }
  std::vector<bool> active =
      generated_sole && o.footprint_outline
          // The top's vertices; after a negative image (remeshed), the upward-facing ones.
          ? (o.negative_image ? ActiveByRule(scenario.support, ActiveRule::kUpwardFacing, 0.5)
                              : outline_top)
          : generated_sole
                ? ActiveWhere(scenario.support,
                              [&](const Eigen::Vector3d& p) {
                                return OnProfileBlockTop(sole, p - Eigen::Vector3d(shift_x, 0, 0));
                              })
                : ActiveByRule(scenario.support, o.user_support.active,
                               o.user_support.min_normal_y);
  std::ostringstream support;
  if (generated_sole && o.footprint_outline) {
    support << "fitted sole: the footprint + " << o.sole_margin << " m, " << o.sole_thickness
            << " m thick, top spacing " << o.sole_top_spacing << " m";
  } else if (generated_sole) {
    support << "sole " << sole.width << " x " << o.sole_thickness << " x "
            << sole.front_z - sole.back_z << " m, top spacing " << o.sole_top_spacing << " m";
  } else {
    support << "user support " << o.user_support.path;
  }
  std::ostringstream description;
  description << "shoe sole (" << o.preset << (o.negative_image ? ", negative image" : ", flat")
              << ", lean " << o.lean_torque << " N m";
  // The foot's regions from its heel; none for a user's body whose heel end cannot be told
  // (its load through the core's centre: with a load point, LoadPointTorque refused it above).
  try {
    scenario.regions.from_min_z =
        o.user_body.empty() ||
        HeelAtMinZ(scenario.body->rest().vertices, o.user_body.anatomy.heel_end, "shoe regions");
    scenario.regions.names = FootRegionNames();
    scenario.regions.ends = FootRegionEnds();
  } catch (const InputError&) {
  }
  if (o.load_point) description << ", load at " << 100 * *o.load_point << " % from the heel";
  if (balance_roll || stance_roll || roll != 0)
    description << ", roll " << r.roll_radians / RollBalanceOptions::kDegree << " degrees";
  description << ")";
  FinishScenario(description.str(), support.str(), o.contact_stiffness, o.free_fall_mass_scale,
                 o.design_space, std::move(active), &scenario, &r);
  return scenario;
}

}  // namespace ergo
