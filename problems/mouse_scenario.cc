#include "problems/mouse_scenario.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "ergo/body/core_lock.h"
#include "ergo/contact/support_validation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/seconds_since.h"
#include "problems/mesh_booleans.h"

namespace ergo {
namespace {

// An icosphere whose edges (≈ 1.05 r / 2^s) are at most `edge`.
TriMesh FineSphere(const Ball& ball, double edge) {
  const int subdivisions =
      std::max(1, static_cast<int>(std::ceil(std::log2(1.05 * ball.radius / edge))));
  return MakeIcosphere(ball.radius, subdivisions, ball.centre);
}

}  // namespace

TriMesh MakeTwoBallMouse(const MouseShape& shape) {
  if (!(shape.rear.radius > 0) || !(shape.front.radius > 0) || !(shape.edge_length > 0) ||
      shape.taubin_iterations < 0) {
    throw InputError("mouse", "shape", "radii and edge length must be positive",
                     "e.g. radii 0.036 and 0.030 m, edge 0.004 m");
  }
  const double distance = (shape.rear.centre - shape.front.centre).norm();
  if (!(distance > std::abs(shape.rear.radius - shape.front.radius) + shape.edge_length) ||
      !(distance < shape.rear.radius + shape.front.radius - shape.edge_length)) {
    throw InputError("mouse", "shape",
                     "the two balls must overlap without one containing the other",
                     "move the centres so that |r1 - r2| < distance < r1 + r2");
  }
  // The union's crease and the icospheres' facets are replaced by an even mesh of the
  // edge length (its triangles' areas are the pressures' denominators), then smoothed.
  const BooleanResult joined = MeshUnion(FineSphere(shape.rear, 0.5 * shape.edge_length),
                                         FineSphere(shape.front, 0.5 * shape.edge_length), "mouse");
  TriMesh mouse = RemeshIsotropic(joined.mesh, {}, shape.edge_length, 5);
  if (shape.taubin_iterations > 0) {
    TaubinParameters taubin;
    taubin.iterations = shape.taubin_iterations;
    mouse = TaubinSmooth(mouse, taubin);
  }
  ValidateSupportMesh(mouse, "mouse");
  return mouse;
}

MouseScenarioOptions MouseScenarioOptions::FromPreset(const std::string& preset) {
  MouseScenarioOptions o;
  o.preset = preset;
  if (preset == "quick") return o;
  if (preset == "paper") {
    o.body_edge_length = 0.0043;
    o.sliver_bound_degrees = 12;
    o.mouse.edge_length = 0.0016;
    return o;
  }
  throw InputError("mouse scenario", "preset", "unknown preset \"" + preset + "\"",
                   "use quick or paper");
}

Scenario MakeMouseScenario(const MouseScenarioOptions& o, ScenarioBuildReport* report) {
  ScenarioBuildReport local;
  ScenarioBuildReport& r = report != nullptr ? *report : local;
  if (!(o.body_edge_length > 0) || !(o.contact_stiffness > 0) || !(o.free_fall_mass_scale > 0) ||
      !(o.start_gap >= 0)) {
    throw InputError("mouse scenario", "options",
                     "edge length, contact stiffness and free-fall scale must be positive, the "
                     "gap non-negative",
                     "check the mouse options");
  }
  Scenario scenario;
  scenario.name = "mouse";
  LayeredBodyOptions load;
  load.lock = ParseCoreLock(o.lock, "mouse lock");

  scenario.body = MakeScenarioBody(
      "hand",
      [&] {
        return MakeHandSpec(o.hand, {o.mouse.rear, o.mouse.front});
      },
      o.body_edge_length, o.sliver_bound_degrees, o.user_body, load, &r);

  auto start = std::chrono::steady_clock::now();
  const bool generated_mouse = o.user_support.empty();
  scenario.support = generated_mouse ? MakeTwoBallMouse(o.mouse) : LoadUserSupport(o.user_support);
  r.support_seconds = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  scenario.start = StartAbove(*scenario.body, scenario.support, o.start_gap, "mouse");
  scenario.design.placement_gap = o.start_gap;
  r.start_seconds = SecondsSince(start);
  if (o.negative_image) UseNegativeImage(o.negative, o.start_gap, &scenario, &r);
  std::vector<bool> active =
      generated_mouse
          ? ActiveWhere(scenario.support,
                        [&](const Eigen::Vector3d& p) { return p.y() > o.designed_above_y; })
          : ActiveByRule(scenario.support, o.user_support.active, o.user_support.min_normal_y);
  std::ostringstream support;
  if (generated_mouse) {
    support << "two-ball mouse (radii " << o.mouse.rear.radius << ", " << o.mouse.front.radius
            << " m), edge " << o.mouse.edge_length << " m, " << o.mouse.taubin_iterations
            << " Taubin iterations";
  } else {
    support << "user support " << o.user_support.path;
  }
  FinishScenario(
      std::string("mouse (") + o.preset + (o.negative_image ? ", negative image)" : ", neutral)"),
      support.str(), o.contact_stiffness, o.free_fall_mass_scale, o.design_space,
      std::move(active), &scenario, &r);
  return scenario;
}

}  // namespace ergo
