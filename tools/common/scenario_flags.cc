#include "tools/common/scenario_flags.h"

#include <functional>
#include <vector>

#include <gflags/gflags.h>

#include "ergo/mesh/input_error.h"
#include "problems/bump_scenario.h"
#include "tools/common/scene_flags.h"
#include "tools/common/soft_support_flags.h"

DEFINE_string(scenario, "bump",
              "the design scenario: chair, shoe, mouse (paper §5; --preset, --negative_image) or "
              "bump (a soft ball on a bumpy plate)");

// --scenario=bump: a soft ball on a plate with a Gaussian bump (problems/bump_scenario.h).
DEFINE_double(bump_ball_radius, 0.05, "bump: ball radius, m");
DEFINE_double(bump_core_radius, 0.03, "bump: rigid core radius, m");
DEFINE_double(bump_youngs_modulus, 1e4, "bump: tissue Young's modulus, Pa");
DEFINE_double(bump_edge_length, 0.012, "bump: target tet edge length of the ball, m");
DEFINE_int32(bump_plate_cells, 16, "bump: plate top-face cells per side");
DEFINE_double(bump_height, 0.004, "bump: bump height, m");
DEFINE_double(bump_width, 0.015, "bump: Gaussian sigma of the bump, m");
DEFINE_double(bump_contact_stiffness, 3e7, "bump: contact stiffness κ, Pa/m");

namespace ergo {
namespace {

Scenario MakeBumpFromFlags() {
  BumpScenarioOptions options;
  options.ball_radius = FLAGS_bump_ball_radius;
  options.core_radius = FLAGS_bump_core_radius;
  options.youngs_modulus = FLAGS_bump_youngs_modulus;
  options.edge_length = FLAGS_bump_edge_length;
  options.plate_cells = FLAGS_bump_plate_cells;
  options.bump_height = FLAGS_bump_height;
  options.bump_width = FLAGS_bump_width;
  options.contact_stiffness = FLAGS_bump_contact_stiffness;
  if (!(options.youngs_modulus > 0) || !(options.edge_length > 0) ||
      !(options.contact_stiffness > 0) || options.plate_cells < 1) {
    throw InputError("--bump_*", "",
                     "Young's modulus, edge length, contact stiffness and plate cells must be "
                     "positive",
                     "e.g. --bump_youngs_modulus=1e4 --bump_edge_length=0.012");
  }
  return MakeBumpScenario(options);
}

struct ScenarioEntry {
  const char* name;
  std::function<Scenario()> make;
};

const std::vector<ScenarioEntry>& Table() {
  static const std::vector<ScenarioEntry> table = {
      {"chair", MakeChairFromFlags},
      {"shoe", MakeShoeFromFlags},
      {"mouse", MakeMouseFromFlags},
      {"bump", MakeBumpFromFlags},
  };
  return table;
}

}  // namespace

std::string ScenarioNames() {
  std::string names;
  for (const ScenarioEntry& entry : Table())
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

Scenario ScenarioFromFlags() {
  CheckSoftSupportFlags();  // before the scene is built
  for (const ScenarioEntry& entry : Table()) {
    if (FLAGS_scenario != entry.name) continue;
    Scenario scenario = entry.make();
    ApplySoftSupportFlags(&scenario);  // --support_model=soft: the design moves foam
    return scenario;
  }
  throw InputError("--scenario", "", "unknown scenario \"" + FLAGS_scenario + "\"",
                   "use one of: " + ScenarioNames());
}

}  // namespace ergo
