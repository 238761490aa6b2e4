#include "tools/ergo_validate/simulated_contact.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include "ergo/body/body_state.h"
#include "ergo/ergonomics/plate_reading.h"
#include "ergo/mesh/input_error.h"
#include "tools/common/design_flags.h"
#include "tools/common/run_signals.h"
#include "tools/common/scenario_flags.h"

namespace ergo {
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
  if (!LoadSeenAlongY(load)) {
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
  return SkinMapFromBelow(body, DeformedPositions(body, report.evaluation.equilibrium.state),
                          report.pressures.human.pressure);
}

}  // namespace ergo
