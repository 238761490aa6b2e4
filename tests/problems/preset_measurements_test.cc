// Measurements of every scenario preset for problems/README.md (not a test: it asserts
// nothing and the paper presets take minutes). Run with
//   problems_tests --gtest_also_run_disabled_tests --gtest_filter='*MeasurePresets*'
// (ERGO_MEASURE=chair,quick,flat limits it to matching scenario, preset and start).
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/design/design_problem.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/split_list.h"
#include "problems/chair_scenario.h"
#include "problems/mouse_scenario.h"
#include "problems/shoe_scenario.h"

namespace ergo {
namespace {

bool Selected(const std::string& scenario, const std::string& preset, const std::string& start) {
  const char* filter = std::getenv("ERGO_MEASURE");
  if (filter == nullptr) return true;
  for (const std::string& item : SplitList(filter, ',')) {
    if (item != scenario && item != preset && item != start) return false;
  }
  return true;
}

void Measure(const std::string& scenario_name, const std::string& preset, bool negative,
             const std::function<Scenario(ScenarioBuildReport*)>& make) {
  const std::string start_name = negative ? "negative" : "flat";
  if (!Selected(scenario_name, preset, start_name)) return;
  const auto begin = std::chrono::steady_clock::now();
  ScenarioBuildReport report;
  const Scenario scenario = make(&report);
  const double build = SecondsSince(begin);
  DesignProblem problem = scenario.MakeProblem();
  const DesignEvaluation e = problem.Evaluate(problem.InitialDesign(), false);
  const EquilibriumResult& q = e.equilibrium;
  std::cout << "\n## " << scenario_name << " " << preset << " " << start_name << "\n"
            << scenario.description << "\n"
            << report.body << "\n"
            << report.support << "\n";
  if (!report.negative_image.empty()) std::cout << report.negative_image << "\n";
  std::cout << "build " << build << " s (body " << report.body_seconds << ", support "
            << report.support_seconds << ", placement " << report.start_seconds
            << ", negative image " << report.negative_image_seconds << ")\n"
            << "initial equilibrium: " << q.BriefReport() << "\n"
            << "contact force " << q.contact_force.transpose() << " N, load "
            << scenario.body->TotalLoad().transpose() << " N\n"
            << "initial zeta " << e.zeta << " (human " << e.zeta_human << ", support "
            << e.zeta_support << "), evaluation " << e.timing.BriefReport() << "\n"
            << "| " << scenario_name << " | " << preset << " | " << start_name << " | "
            << report.body_vertices << " | " << report.support_vertices << " ("
            << report.active_vertices << ") | " << report.total_mass << " | "
            << -scenario.body->TotalLoad().y() << " | "
            << scenario.design.equilibrium.contact_stiffness << " | " << build << " | "
            << q.total_seconds << " (" << q.iterations << ") | " << q.max_penetration * 1e3 << " | "
            << e.zeta << " |\n";
}

TEST(Problems, DISABLED_MeasurePresets) {
  for (const std::string preset : {"quick", "paper"}) {
    for (bool negative : {false, true}) {
      Measure("chair", preset, negative, [&](ScenarioBuildReport* r) {
        ChairScenarioOptions o = ChairScenarioOptions::FromPreset(preset);
        o.negative_image = negative;
        return MakeChairScenario(o, r);
      });
      Measure("shoe", preset, negative, [&](ScenarioBuildReport* r) {
        ShoeScenarioOptions o = ShoeScenarioOptions::FromPreset(preset);
        o.negative_image = negative;
        return MakeShoeScenario(o, r);
      });
      Measure("mouse", preset, negative, [&](ScenarioBuildReport* r) {
        MouseScenarioOptions o = MouseScenarioOptions::FromPreset(preset);
        o.negative_image = negative;
        return MakeMouseScenario(o, r);
      });
    }
  }
}

}  // namespace
}  // namespace ergo
