// ergo_paper's plan (tools/common/paper_plan.h): which runs each table needs, that a run two
// tables share is planned once, the flags each run gets, and refused presets and experiments.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tools/common/paper_plan.h"

namespace ergo {
namespace {

std::set<std::string> All() { return {PaperExperiments().begin(), PaperExperiments().end()}; }

bool Has(const std::vector<std::string>& arguments, const std::string& flag) {
  return std::find(arguments.begin(), arguments.end(), flag) != arguments.end();
}

TEST(ToolsPaperPlan, EveryTableGetsItsRowsAndSharedRunsArePlannedOnce) {
  const PaperPlan plan = MakePaperPlan(DefaultPaperSettings(PaperPreset::kQuick), All());
  EXPECT_EQ(plan.table1.size(), 6u);       // 3 scenes × flat, negative image
  EXPECT_EQ(plan.table2.size(), 6u);       // raw: γ = 0 + 4 values; filtered γ = 0
  EXPECT_EQ(plan.depth_sweep.size(), 6u);  // 1 … 6 cm
  EXPECT_EQ(plan.exponents.size(), 3u);
  EXPECT_EQ(plan.baselines.size(), 12u);  // 3 scenes × ergo, S&R, P2S, ergo from S&R
  // Shared: Table 2's filtered row is Table 1's mouse flat run; the 5 cm depth is Table 1's
  // chair negative image; exponent 3 and the baselines' ergo row are Table 1's flat runs.
  EXPECT_EQ(plan.table2.back(), plan.table1[4]);
  EXPECT_EQ(plan.depth_sweep[4], plan.table1[1]);
  EXPECT_EQ(plan.exponents[1], plan.table1[2]);
  EXPECT_EQ(plan.baselines[0], plan.table1[0]);
  // 6 + 5 + 5 + 2 + 9 distinct runs.
  EXPECT_EQ(plan.runs.size(), 27u);
  std::set<std::string> names;
  for (const PaperRun& run : plan.runs) names.insert(run.Name());
  EXPECT_EQ(names.size(), plan.runs.size());
  EXPECT_EQ(plan.runs[plan.table1[1]].Name(), "chair__negative-image");
  EXPECT_EQ(plan.runs[plan.depth_sweep[0]].Name(), "chair__negative-image__depth=0.01");
  EXPECT_EQ(plan.runs[plan.table2[1]].Name(), "mouse__raw-vertices__gamma_power=-3");
}

TEST(ToolsPaperPlan, OnlyTheChosenExperimentsArePlanned) {
  const PaperPlan plan = MakePaperPlan(DefaultPaperSettings(PaperPreset::kQuick), {"baselines"});
  EXPECT_TRUE(plan.table1.empty());
  EXPECT_EQ(plan.baselines.size(), 12u);
  EXPECT_EQ(plan.runs.size(), 12u);
}

TEST(ToolsPaperPlan, RunsGetTheirSceneFlagfileThePresetAndTheirOwnFlags) {
  PaperSettings settings = DefaultPaperSettings(PaperPreset::kPaper);
  settings.extra = {"--max_seconds=60"};
  const PaperPlan plan = MakePaperPlan(settings, All());
  const PaperRun& mouse_gamma = plan.runs[plan.table2[2]];
  const std::vector<std::string> a = mouse_gamma.Arguments(settings, "/d/mouse.flags");
  EXPECT_EQ(a.front(), "--flagfile=/d/mouse.flags");  // first, so every later flag overrides it
  EXPECT_TRUE(Has(a, "--preset=paper"));
  EXPECT_TRUE(Has(a, "--max_evals=20"));
  EXPECT_TRUE(Has(a, "--placement_checks=false"));
  EXPECT_TRUE(Has(a, "--robust_tilt_deg=0"));  // one placement: the flagfile's tilts off too
  EXPECT_TRUE(Has(a, "--parameterization=normal"));
  EXPECT_TRUE(Has(a, "--gamma=auto"));
  EXPECT_TRUE(Has(a, "--gamma_power=-1"));
  EXPECT_EQ(a.back(), "--max_seconds=60");    // the user's flags last
  EXPECT_DOUBLE_EQ(PaperGammaFor(-1), 1e13);  // the paper's best γ
  EXPECT_DOUBLE_EQ(PaperGammaFor(3), 1e17);

  const PaperRun& depth = plan.runs[plan.depth_sweep[2]];
  const std::vector<std::string> d = depth.Arguments(settings, "c.flags");
  EXPECT_TRUE(Has(d, "--negative_image=true"));
  EXPECT_TRUE(Has(d, "--negative_image_depth=0.03"));
  EXPECT_TRUE(Has(d, "--gamma=0"));

  // The mouse's Sit & Relax is pushed 1 cm in (5 cm has no equilibrium); the others 5 cm.
  for (size_t i : plan.baselines) {
    const PaperRun& run = plan.runs[i];
    if (run.designer != "sit-and-relax") continue;
    const std::vector<std::string> b = run.Arguments(settings, "f");
    EXPECT_TRUE(Has(b, run.scene == "mouse" ? "--baseline_depth=0.01" : "--baseline_depth=0.05"))
        << run.Name();
    EXPECT_EQ(run.MethodLabel(), "Sit & Relax");
  }
  const PaperRun& from = plan.runs[plan.baselines[3]];
  EXPECT_EQ(from.MethodLabel(), "ergo from Sit & Relax");
  EXPECT_TRUE(Has(from.Arguments(settings, "f"), "--start_designer=sit-and-relax"));
}

TEST(ToolsPaperPlan, PresetsDifferInResolutionAndBudget) {
  const PaperSettings quick = DefaultPaperSettings(PaperPreset::kQuick);
  const PaperSettings paper = DefaultPaperSettings(PaperPreset::kPaper);
  EXPECT_LT(quick.max_evals, paper.max_evals);
  EXPECT_FALSE(quick.placement_checks);  // the tables score the centred placement
  EXPECT_FALSE(paper.placement_checks);
  EXPECT_EQ(ParsePaperPreset("quick"), PaperPreset::kQuick);
  EXPECT_EQ(PaperPresetName(ParsePaperPreset("paper")), "paper");
}

TEST(ToolsPaperPlan, UnknownPresetOrExperimentIsAnInputErrorNamingTheFlag) {
  try {
    ParsePaperPreset("fast");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--preset"), std::string::npos) << e.what();
  }
  try {
    MakePaperPlan(DefaultPaperSettings(PaperPreset::kQuick), {"table1", "table3"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--experiments"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("table3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ergo
