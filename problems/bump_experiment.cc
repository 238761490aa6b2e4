#include "problems/bump_experiment.h"

#include <algorithm>
#include <cmath>

#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/pressure_statistics.h"

namespace ergo {

std::vector<BumpSweepPoint> RunBumpFrequencySweep(const BumpScenarioOptions& base,
                                                  std::vector<double> widths) {
  std::sort(widths.begin(), widths.end(), std::greater<double>());  // increasing frequency
  BumpScenarioOptions options = base;
  const double narrowest = widths.empty() ? base.bump_width : widths.back();
  options.plate_cells = std::max(
      base.plate_cells, static_cast<int>(std::ceil(2 * base.plate_half_width / (0.5 * narrowest))));
  options.bump_centre = Eigen::Vector2d::Zero();  // under the ball's centre

  std::vector<BumpSweepPoint> points;
  BodyState warm;
  bool have_warm = false;
  for (double width : widths) {
    options.bump_width = width;
    const Scenario scenario = MakeBumpScenario(options);
    const Support support(scenario.support, "bump plate");
    EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
    const BodyState start =
        have_warm ? warm : PlaceAboveSupport(*scenario.body, scenario.start, support, 1e-3).state;
    const EquilibriumResult result = solver.Solve(support, start);
    BumpSweepPoint point;
    point.width = width;
    point.frequency = 1.0 / width;
    point.converged = result.converged;
    point.message = result.BriefReport();
    point.contact_vertices = result.contact_vertices;
    point.max_penetration = result.max_penetration;
    if (result.converged) {
      warm = result.state;
      have_warm = true;
      for (int exponent : {2, 3, 4}) {
        const ContactPressureEvaluator evaluator(*scenario.body, scenario.support,
                                                 PressureCostOptions{exponent, 1.0});
        const ContactPressures pressures =
            evaluator.Evaluate(solver.last_evaluation().contacts, support.vertex_areas());
        point.zeta[exponent - 2] = pressures.human.cost + pressures.support.cost;
        if (exponent == 3) {
          point.peak_pressure =
              ComputePressureStatistics(pressures.human.pressure, scenario.body->skin().rest_areas)
                  .peak;
        }
      }
    }
    points.push_back(point);
  }
  if (!points.empty() && points.front().converged) {
    for (BumpSweepPoint& p : points)
      for (int k = 0; k < 3; ++k) p.rescaled[k] = p.zeta[k] / points.front().zeta[k];
  }
  return points;
}

}  // namespace ergo
