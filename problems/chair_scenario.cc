#include "problems/chair_scenario.h"

#include <chrono>
#include <memory>
#include <sstream>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"
#include "problems/load_point.h"

namespace ergo {
ChairScenarioOptions ChairScenarioOptions::FromPreset(const std::string& preset) {
  ChairScenarioOptions o;
  o.preset = preset;
  if (preset == "quick") return o;
  if (preset == "paper") {
    o.body_edge_length = 0.019;
    o.sliver_bound_degrees = 12;
    o.block.top_spacing = 0.003;
    o.block.wall_spacing = 0.02;
    return o;
  }
  throw InputError("chair scenario", "preset", "unknown preset \"" + preset + "\"",
                   "use quick or paper");
}

Scenario MakeChairScenario(const ChairScenarioOptions& o, ScenarioBuildReport* report) {
  ScenarioBuildReport local;
  ScenarioBuildReport& r = report != nullptr ? *report : local;
  if (!(o.body_edge_length > 0) || !(o.contact_stiffness > 0) || !(o.free_fall_mass_scale > 0) ||
      !(o.start_gap >= 0) || !(o.upper_body_load >= 0) ||
      (o.load_point && !(*o.load_point >= 0 && *o.load_point <= 1))) {
    throw InputError("chair scenario", "options",
                     "edge length, contact stiffness and free-fall scale must be positive, the "
                     "gap and the upper-body load non-negative, the load point in [0, 1]",
                     "check the chair options");
  }
  Scenario scenario;
  scenario.name = "chair";
  LayeredBodyOptions load;
  load.lock = ParseCoreLock(o.lock, "chair lock");
  load.external_force = Eigen::Vector3d(0, -o.upper_body_load, 0);

  // Body.
  scenario.body = MakeScenarioBody(
      "seated body", [&] { return MakeSeatedBodySpec(o.body); }, o.body_edge_length,
      o.sliver_bound_degrees, o.user_body, load, &r);

  // Support.
  auto start = std::chrono::steady_clock::now();
  const bool generated_block = o.user_support.empty();
  scenario.support = generated_block ? MakeProfileBlock(o.block) : LoadUserSupport(o.user_support);
  if (o.load_point) {
    // The seat's depth: the support's extent along z, from its back (smallest z).
    const double back = scenario.support.vertices.col(2).minCoeff();
    const double depth = scenario.support.vertices.col(2).maxCoeff() - back;
    Eigen::Vector3d point = scenario.body->core_centre();
    point.z() = back + *o.load_point * depth;
    auto loaded = std::make_shared<LayeredBody>(*scenario.body);
    loaded->SetExternalWrench(
        load.external_force,
        load.external_torque + TorqueThroughPoint(*scenario.body, load.external_force, point));
    scenario.body = loaded;
  }
  r.support_seconds = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  scenario.start = StartAbove(*scenario.body, scenario.support, o.start_gap, "chair");
  scenario.design.placement_gap = o.start_gap;
  r.start_seconds = SecondsSince(start);
  if (o.negative_image) {
    UseNegativeImage(o.negative, o.start_gap, &scenario, &r);
  }
  std::vector<bool> active =
      generated_block
          ? ActiveWhere(scenario.support,
                        [&](const Eigen::Vector3d& p) { return OnProfileBlockTop(o.block, p); })
          : ActiveByRule(scenario.support, o.user_support.active, o.user_support.min_normal_y);
  std::ostringstream support;
  if (generated_block) {
    support << "block " << o.block.width << " x " << o.block.top_y - o.block.bottom_y << " x "
            << o.block.front_z - o.block.back_z << " m, front arc " << o.block.front_radius
            << " m, top spacing " << o.block.top_spacing << " m";
  } else {
    support << "user support " << o.user_support.path;
  }
  FinishScenario("chair (" + o.preset + (o.negative_image ? ", negative image)" : ", flat)"),
                 support.str(), o.contact_stiffness, o.free_fall_mass_scale, o.design_space,
                 std::move(active), &scenario, &r);
  return scenario;
}

}  // namespace ergo
