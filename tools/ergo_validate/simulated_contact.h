// The simulated side of ergo_validate: the scene the flags pose (ergo_optimize's scenarios:
// --flagfile=data/shoe.flags, a --preset, a user's --body_dir or --support_mesh, the design
// flags), solved once with the body placed afresh on the support as given — what ergo_optimize
// reports for its initial design — and the contact pressures of that equilibrium seen along y
// on the support's plane (x, z). The same library calls as ergo_optimize's: ScenarioFromFlags,
// ApplyDesignFlags, DesignProblem with DesignPlacement::kFresh, ReportDesign.
#pragma once

#include <string>

#include "ergo/ergonomics/planar_pressure_map.h"
#include "problems/scenario.h"
#include "tools/common/run_outputs.h"

namespace ergo {

// Which surface's pressures are the simulated map.
enum class SimulatedSide {
  // The skin's: the forces the solver applied (their total is the load) over the area each
  // skin vertex covers seen from below, on the deformed skin's triangles that face down —
  // what a plate under the foot measures (PlanarPressureMap::FromVertexForces).
  kSkin,
  // The support's: p = κg sampled at support vertices inside the skin (the score's second
  // half). On the quick shoe's 10 mm sole they over-integrate the load by about 70 %.
  kSupport,
};
bool ParseSimulatedSide(const std::string& name, SimulatedSide* side);
const char* SimulatedSideName(SimulatedSide side);

// The scene from its flags with the design flags applied and Ctrl-C wired to its solves.
// Throws InputError for unusable flags.
Scenario PrepareScenario();

// The magnitude of the scene's load, N, checked to act along −y (within 10°: the maps are
// seen along y). Throws InputError naming the scene otherwise.
double SceneLoad(const Scenario& scenario);

// One equilibrium of the body placed afresh on the scene's support. report.evaluation.ok
// says whether it converged (message: why not).
DesignReport SolveOnSupport(const Scenario& scenario);

// The simulated map of `report` on `side`.
PlanarPressureMap SimulatedPressureMap(const Scenario& scenario, const DesignReport& report,
                                       SimulatedSide side);

}  // namespace ergo
