// ergo_population end to end on the shipped four-foot shoe population (quick preset, one
// placement, a budget of a few evaluations): every output is written and consistent, the
// population design lowers the population's score placed afresh, and the run under
// `mpirun -np 3` (four bodies on three ranks: one rank holds two) gives the same design and
// the same per-body figures bit for bit. A body that finds no equilibrium stops every rank
// with its name; bad flags and files exit 2 naming the culprit; --generate writes a
// population that reads back.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/json.h"
#include "problems/population.h"
#include "tests/support/test_paths.h"
#include "tests/support/text_files.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct ToolRun {
  int status = -1;
  std::string output;
};

ToolRun RunTool(std::vector<std::string> command, const std::string& log) {
  ChildOptions options;
  options.output = log;
  const ChildProcessResult run = RunChildProcess(command, options);
  return {run.started && run.signal == 0 ? run.exit_code : -1, testing::ReadTextFile(log)};
}

// The population run of these tests: three evaluations, no pictures.
std::vector<std::string> PopulationCommand(const std::string& population, const fs::path& out,
                                           bool compare_mean_body) {
  return {ERGO_BIN_DIR "/ergo_population",
          "--population=" + population,
          "--robust_placements=1",
          "--max_evals=3",
          "--round_evals=3",
          "--candidates=1",
          "--plot=false",
          "--progress=false",
          std::string("--compare_mean_body=") + (compare_mean_body ? "true" : "false"),
          "--out=" + out.string()};
}

std::string Mpirun() {
  for (const char* path : {"/usr/bin/mpirun", "/usr/local/bin/mpirun"})
    if (fs::exists(path)) return path;
  return "";
}

TEST(ToolsPopulation, FourFeetShareOneSoleAndEveryOutputIsWritten) {
  if (testing::SanitizedBuild()) GTEST_SKIP() << "four quick feet are a Release-build run";
  const fs::path dir = testing::MakeScratchDir("population");
  const fs::path out = dir / "out";
  const ToolRun run =
      RunTool(PopulationCommand(testing::SourcePath("data/shoe_population.json"), out, true),
              (dir / "log").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const Json summary = ReadJsonFile((out / "summary.json").string());
  EXPECT_EQ(summary["objective"], "mean");
  const double initial = summary["initial_score"].get<double>();
  const double optimized = summary["optimized_score"].get<double>();
  // mean of r_b = 1 at the start; the design lowers it placed afresh.
  EXPECT_DOUBLE_EQ(initial, 1.0);
  EXPECT_LT(optimized, initial);
  ASSERT_EQ(summary["bodies"].size(), 4u);
  double mean = 0;
  for (const Json& body : summary["bodies"]) {
    const double r = body["optimized_score"].get<double>() / body["initial_score"].get<double>();
    mean += 0.25 * r;
    EXPECT_NEAR(body["reduction_percent"].get<double>(), 100 * (1 - r), 1e-9);
    EXPECT_GT(body["initial_peak_pressure"].get<double>(), 1e4);  // a foot standing: ≥ 10 kPa
    EXPECT_GT(body["optimized_peak_pressure"].get<double>(), 1e4);
    EXPECT_TRUE(body.contains("mean_body_design_reduction_percent"));
    for (const char* tag : {"_initial.vtu", "_optimized.vtu"}) {
      EXPECT_TRUE(fs::exists(out / ("body_" + body["name"].get<std::string>() + tag)));
      EXPECT_TRUE(fs::exists(out / ("support_" + body["name"].get<std::string>() + tag)));
    }
  }
  // The population score is the mean of the bodies' relative scores (weights 1/4 each).
  EXPECT_NEAR(optimized, mean, 1e-12);
  EXPECT_EQ(summary["bodies"][0]["name"], "small-soft");
  EXPECT_TRUE(summary.contains("mean_body_design"));
  double worst = INFINITY;
  for (const Json& body : summary["bodies"])
    worst = std::min(worst, body["reduction_percent"].get<double>());
  EXPECT_DOUBLE_EQ(summary["worst_body_reduction_percent"].get<double>(), worst);
  for (const char* file :
       {"summary.md", "bodies.csv", "history.csv", "population.json", "support_initial.stl",
        "support_optimized.stl", "support_optimized.ply", "support_mean_body.stl"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  EXPECT_EQ(testing::CountLines(testing::ReadTextFile((out / "bodies.csv").string())), 5);
  // The population written beside the results reads back as the one run.
  EXPECT_EQ(ReadPopulationFile((out / "population.json").string()).bodies.size(), 4u);
  fs::remove_all(dir);
}

TEST(ToolsPopulation, UnderMpirunTheRanksGiveTheSingleProcessDesignBitForBit) {
  if (testing::SanitizedBuild()) GTEST_SKIP() << "MPI is not built with the sanitizers";
  const std::string mpirun = Mpirun();
  if (mpirun.empty()) GTEST_SKIP() << "mpirun not found (apt-get install openmpi-bin)";
  const fs::path dir = testing::MakeScratchDir("population_mpi");
  const std::string population = testing::SourcePath("data/shoe_population.json");
  const ToolRun single =
      RunTool(PopulationCommand(population, dir / "single", false), (dir / "single.log").string());
  ASSERT_EQ(single.status, 0) << single.output;
  std::vector<std::string> command = {mpirun, "--allow-run-as-root", "--oversubscribe", "-np", "3"};
  for (const std::string& part : PopulationCommand(population, dir / "ranks", false))
    command.push_back(part);
  command.push_back("--mpi");
  const ToolRun ranks = RunTool(command, (dir / "ranks.log").string());
  ASSERT_EQ(ranks.status, 0) << ranks.output;
  EXPECT_NE(ranks.output.find("on 3 rank(s)"), std::string::npos) << ranks.output;
  // The same bits: the per-body figures (17 digits) and the design's mesh.
  EXPECT_EQ(testing::ReadTextFile((dir / "single/bodies.csv").string()),
            testing::ReadTextFile((dir / "ranks/bodies.csv").string()));
  EXPECT_EQ(testing::ReadTextFile((dir / "single/support_optimized.ply").string()),
            testing::ReadTextFile((dir / "ranks/support_optimized.ply").string()));
  const Json a = ReadJsonFile((dir / "single/summary.json").string());
  const Json b = ReadJsonFile((dir / "ranks/summary.json").string());
  EXPECT_EQ(a["optimized_score"].get<double>(), b["optimized_score"].get<double>());
  EXPECT_EQ(b["ranks"], 3);
  EXPECT_GT(b["reduction_bytes_per_evaluation"].get<long long>(), 0);
  // Body VTUs come from the ranks that own the bodies (body 1 lives on rank 1).
  EXPECT_TRUE(fs::exists(dir / "ranks/body_medium_optimized.vtu"));
  fs::remove_all(dir);
}

TEST(ToolsPopulation, ABodyWithoutEquilibriumStopsEveryRankNamingIt) {
  if (testing::SanitizedBuild()) GTEST_SKIP() << "quick feet are a Release-build run";
  const fs::path dir = testing::MakeScratchDir("population_fail");
  // The second body's Newton solve gets one iteration: it cannot reach equilibrium.
  std::ofstream(dir / "p.json") << R"({"flagfile": ")" << testing::SourcePath("data/shoe.flags")
                                << R"(", "bodies": [
      {"name": "fine", "flags": {}},
      {"name": "starved", "flags": {"max_newton_iterations": 1}}]})";
  std::vector<std::vector<std::string>> commands = {
      PopulationCommand((dir / "p.json").string(), dir / "out", false)};
  const std::string mpirun = Mpirun();
  if (!mpirun.empty()) {
    std::vector<std::string> command = {mpirun, "--allow-run-as-root", "--oversubscribe", "-np",
                                        "2"};
    for (const std::string& part : commands.front()) command.push_back(part);
    command.push_back("--mpi");
    commands.push_back(command);
  }
  for (const std::vector<std::string>& command : commands) {
    const ToolRun run = RunTool(command, (dir / "log").string());
    EXPECT_EQ(run.status, 1) << run.output;  // a failed computation, not a hang or a crash
    EXPECT_NE(run.output.find("body starved"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("did not reach equilibrium"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out"));  // no partial output
  }
  fs::remove_all(dir);
}

TEST(ToolsPopulation, BadFlagsAndFilesExitTwoNamingTheCulprit) {
  const fs::path dir = testing::MakeScratchDir("population_bad");
  std::ofstream(dir / "twice.json") << R"({"bodies": [{"name": "a"}, {"name": "a"}]})";
  std::ofstream(dir / "unknown.json")
      << R"({"bodies": [{"name": "a", "flags": {"no_such_flag": 1}}]})";
  std::ofstream(dir / "typed.json")
      << R"({"bodies": [{"name": "a", "flags": {"shoe_body_mass": "heavy"}}]})";
  const std::string shipped = testing::SourcePath("data/shoe_population.json");
  const std::string out = "--out=" + (dir / "out").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{out}, "--population"},
      {{"--population=" + shipped, "--objective=median", out}, "--objective"},
      {{"--population=" + shipped, "--cvar_alpha=1", out}, "--cvar_alpha"},
      {{"--population=" + shipped, "--max_evals=0", out}, "--max_evals"},
      {{"--population=" + (dir / "twice.json").string(), out}, "appears twice"},
      {{"--population=" + (dir / "unknown.json").string(), out}, "no_such_flag"},
      {{"--population=" + (dir / "typed.json").string(), out}, "shoe_body_mass"},
      {{"--population=" + (dir / "absent.json").string(), out}, "absent.json"},
      {{"--generate=" + (dir / "g.json").string(), "--vary=shoe_body_mass"}, "FLAG=LOW:HIGH"},
      {{"--generate=" + (dir / "g.json").string(), "--vary=shoe_body_mass=60:90",
        "--support_at=shoe_foot_length=high"},
       "--support_at"},
  };
  for (const auto& [arguments, expected] : cases) {
    std::vector<std::string> command = {ERGO_BIN_DIR "/ergo_population"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const ToolRun run = RunTool(command, (dir / "log").string());
    EXPECT_EQ(run.status, 2) << arguments.front() << ": " << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << run.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

TEST(ToolsPopulation, GenerateWritesAPopulationThatReadsBack) {
  const fs::path dir = testing::MakeScratchDir("population_generate");
  const ToolRun run =
      RunTool({ERGO_BIN_DIR "/ergo_population", "--generate=" + (dir / "g.json").string(),
               "--scene_flagfile=" + testing::SourcePath("data/shoe.flags"), "--count=8",
               "--vary=shoe_foot_length=0.24:0.28,shoe_modulus_scale=0.7:1.3",
               "--support_at=shoe_foot_length=high"},
              (dir / "log").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const PopulationSpec spec = ReadPopulationFile((dir / "g.json").string());
  EXPECT_EQ(spec.bodies.size(), 8u);
  EXPECT_EQ(spec.support.at("shoe_foot_length"), "0.28");
  EXPECT_TRUE(fs::equivalent(spec.flagfile, testing::SourcePath("data/shoe.flags")));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ergo
