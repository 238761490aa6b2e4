// Uses the installed ergo: poses the bump scene (mesh, body, contact, equilibrium and
// design stages) and evaluates φ and its gradient at the flat start. Exit 0 only when the
// equilibrium converged and the numbers are usable.
#include <cmath>
#include <cstdio>

#include "ergo/mesh/input_error.h"
#include "problems/bump_scenario.h"

int main() {
  try {
    ergo::BumpScenarioOptions options;
    options.edge_length = 0.016;  // a coarse ball: the point is linking, not accuracy
    options.plate_cells = 8;
    const ergo::Scenario scenario = ergo::MakeBumpScenario(options);
    ergo::DesignProblem problem = scenario.MakeProblem();
    const ergo::DesignEvaluation evaluation = problem.Evaluate(problem.InitialDesign(), true);
    std::printf("ergo_consumer: %s: φ %.6e, |∇φ| %.3e, %d contact vertices (%s)\n",
                scenario.name.c_str(), evaluation.phi, evaluation.gradient.norm(),
                evaluation.equilibrium.contact_vertices, evaluation.message.c_str());
    const bool usable = evaluation.ok && evaluation.phi > 0 && std::isfinite(evaluation.phi) &&
                        evaluation.gradient.allFinite() && evaluation.gradient.norm() > 0;
    return usable ? 0 : 1;
  } catch (const ergo::InputError& error) {
    std::fprintf(stderr, "ergo_consumer: %s\n", error.what());
    return 2;
  }
}
