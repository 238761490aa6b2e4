#include <iostream>
#include <gtest/gtest.h>
#include "problems/shoe_scenario.h"
namespace ergo {
TEST(Scratch, WarmCost) {
  for (bool springs : {false, true}) {
    ShoeScenarioOptions o = ShoeScenarioOptions::FromPreset("quick");
    Scenario s = MakeShoeScenario(o, nullptr);
    s.design.gamma = 0;
    s.design.equilibrium.contact_support_springs = springs;
    s.design.equilibrium.contact_stiffness = springs ? 8e8 : 1.38e9;
    s.design.placement = DesignPlacement::kFollowed;
    DesignProblem p = s.MakeProblem();
    const Eigen::VectorXd x0 = p.InitialDesign();
    const DesignEvaluation f0 = p.Evaluate(x0, true);
    std::cout << (springs ? "two-way" : "one-way") << " cold " << f0.equilibrium.iterations << " its, " << f0.equilibrium.FullReport() << "\n";
    Eigen::VectorXd d = -f0.gradient;
    d /= p.parameterization().VertexMoves(d).maxCoeff();
    for (double t : {1e-5, 1e-4, 3e-4, 1e-3, 3e-3}) {
      DesignProblem q = p;
      const DesignEvaluation a = q.Evaluate(x0 + t * d, true);
      std::cout << "  move " << t * 1e3 << " mm: " << a.equilibrium.iterations << " its (" << a.equilibrium.projected_steps << " projected, " << a.equilibrium.factorizations << " factorisations, " << a.equilibrium.pcg_iterations << " pcg) " << a.equilibrium.total_seconds << " s, adjoint " << a.adjoint_seconds << " s\n";
    }
  }
}
}
