#include "tools/ergo_validate/simulated_contact.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include "ergo/body/body_state.h"
#include "ergo/mesh/input_error.h"
#include "tools/common/design_flags.h"
#include "tools/common/run_signals.h"
#include "tools/common/scenario_flags.h"

namespace ergo {
namespace {

// Maps are compared seen along y; a load more than 10° off −y would foreshorten them by more
// than 1.5 % (1 − cos 10°) and move the footprint's projection by more than its tilt allows.
constexpr double kMinLoadAlongY = 0.985;  // cos 10°

}  // namespace

bool ParseSimulatedSide(const std::string& name, SimulatedSide* side) {
  for (SimulatedSide s : {SimulatedSide::kSkin, SimulatedSide::kSupport}) {
    if (name == SimulatedSideName(s)) {
      *side = s;
      return true;
    }
  }
  return false;
}

const char* SimulatedSideName(SimulatedSide side) {
  return side == SimulatedSide::kSkin ? "skin" : "support";
}

Scenario PrepareScenario() {
  Scenario scenario = ScenarioFromFlags();
  std::cout << "scenario " << scenario.name << ": " << scenario.description << "\n";
  ApplyDesignFlags(&scenario);
  scenario.design.equilibrium.stop = &StopOnSignals::flag();
  return scenario;
}

double SceneLoad(const Scenario& scenario) {
  const Eigen::Vector3d load = scenario.body->TotalLoad();
  const double magnitude = load.norm();
  if (!(magnitude > 0) || -load.y() < kMinLoadAlongY * magnitude) {
    std::ostringstream what;
    what << "the scene's load (" << load.transpose()
         << ") N does not act along -y: ergo_validate compares maps seen along y";
    throw InputError("--scenario", "", what.str(),
                     "use a scene whose load points down (-y), as ergo's chair, shoe and mouse "
                     "do");
  }
  return magnitude;
}

DesignReport SolveOnSupport(const Scenario& scenario) {
  DesignProblem problem = scenario.MakeProblem();
  problem.set_placement(DesignPlacement::kFresh);
  problem.ClearWarmStarts();
  return ReportDesign(problem, problem.InitialDesign());
}

PlanarPressureMap SimulatedPressureMap(const Scenario& scenario, const DesignReport& report,
                                       SimulatedSide side) {
  if (side == SimulatedSide::kSupport) {
    return PlanarPressureMap::FromSurface(report.support, report.pressures.support.pressure,
                                          report.pressures.support_areas,
                                          PlanarPressureMap::Facing::kUp);
  }
  const LayeredBody& body = *scenario.body;
  const Vertices positions = DeformedPositions(body, report.evaluation.equilibrium.state);
  // ergo's skin pressure is per area at rest: ‖f_v‖ = p_v s_v is the force the solver applied.
  const Eigen::VectorXd force =
      report.pressures.human.pressure.cwiseProduct(body.skin().rest_areas);
  return PlanarPressureMap::FromVertexForces(body.skin().RestSurface(positions), force,
                                             PlanarPressureMap::Facing::kDown);
}

}  // namespace ergo
