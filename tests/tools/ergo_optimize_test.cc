// ergo_optimize end to end: a small budget lowers φ by at least 20 % and writes every
// listed output with valid contents; SIGINT mid-run still leaves complete outputs for the
// best design so far.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "ergo/mesh/json.h"
#include "ergo/mesh/mesh_check.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// The scenario the end-to-end test runs (the issue: the quick shoe sole).
constexpr char kScenarioFlags[] = "--flagfile=" ERGO_SOURCE_DIR "/data/shoe.flags";

bool MatplotlibAvailable() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0 ||
         std::system("python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
}

// The tool is reparented once its shell exits; where nothing reaps it, it lingers as a zombie.
bool IsZombie(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(stat, text);
  const size_t paren = text.rfind(')');
  return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] == 'Z';
}

int RunTool(const std::string& arguments, std::string* output) {
  FILE* pipe =
      popen(("timeout 900 " ERGO_BIN_DIR "/ergo_optimize " + arguments + " 2>&1").c_str(), "r");
  char buffer[4096];
  while (fgets(buffer, sizeof(buffer), pipe)) *output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void ExpectCompleteOutputs(const std::string& dir, bool pictures) {
  for (const char* file :
       {"summary.md", "summary.json", "history.csv", "support_initial.ply", "support_initial.stl",
        "support_optimized.ply", "support_optimized.stl", "body_initial.vtu", "body_optimized.vtu",
        "support_initial.vtu", "support_optimized.vtu"}) {
    EXPECT_TRUE(fs::exists(dir + "/" + file)) << file;
  }
  // The print-ready STL is closed, manifold and free of self-intersections, in millimetres.
  MeshCheckOptions closed;
  closed.require_closed = true;
  closed.unit = LengthUnit::kMillimetre;
  const MeshCheckReport stl = CheckMeshFile(dir + "/support_optimized.stl", closed);
  EXPECT_EQ(stl.ExitCode(), 0) << stl.FullReport();
  // VTU files are complete XML documents.
  for (const char* file : {"body_optimized.vtu", "support_optimized.vtu"}) {
    std::ifstream in(dir + "/" + file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.rfind("<?xml", 0), 0u) << file;
    EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << file;
    EXPECT_NE(text.find("pressure_Pa"), std::string::npos) << file;
  }
  if (pictures) {
    for (const char* png :
         {"pressure_maps.png", "pressure_histograms.png", "displacement.png", "phi_history.png"})
      EXPECT_GT(fs::file_size(dir + "/" + png), 1000u) << png;
  }
  // No temporary file left behind.
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(ToolsOptimize, QuickShoeLowersTheScoreAndWritesEveryOutput) {
  const std::string dir = testing::MakeScratchDir("optimize");
  std::string output;
  ASSERT_EQ(RunTool(std::string(kScenarioFlags) + " --max_evals=40 --out=" + dir, &output), 0)
      << output;
  const Json summary = ReadJsonFile(dir + "/summary.json");
  for (const char* key :
       {"initial_score", "optimized_score", "reduction_percent", "gamma", "wall_s", "body_vertices",
        "support_vertices", "contact_vertices", "initial_max_penetration_m",
        "optimized_max_penetration_m", "initial_peak_pressure_Pa", "optimized_peak_pressure_Pa",
        "fresh_placement_converged", "evaluations", "stop_reason"}) {
    EXPECT_NE(summary.Find(key), nullptr) << key;
  }
  EXPECT_GE(GetNumber(summary, "reduction_percent", "summary"), 20.0) << output;
  EXPECT_LT(GetNumber(summary, "optimized_score", "summary"),
            GetNumber(summary, "initial_score", "summary"));
  EXPECT_LE(GetNumber(summary, "evaluations", "summary"), 40.0);
  ExpectCompleteOutputs(dir, MatplotlibAvailable());
  fs::remove_all(dir);
}

TEST(ToolsOptimize, InterruptLeavesCompleteOutputsForTheBestDesign) {
  const std::string dir = testing::MakeScratchDir("interrupt");
  const std::string log = dir + ".log";
  // Start in the background; send SIGINT once the optimisation has made progress.
  const std::string command = std::string(ERGO_BIN_DIR) + "/ergo_optimize " + kScenarioFlags +
                              " --max_evals=100000 --plot=false --out=" + dir + " > " + log +
                              " 2>&1 & echo $!";
  FILE* pipe = popen(command.c_str(), "r");
  int pid = 0;
  ASSERT_EQ(fscanf(pipe, "%d", &pid), 1);
  pclose(pipe);
  bool started = false;
  for (int wait = 0; wait < 600 && !started; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    started = text.find("iter    2") != std::string::npos;
  }
  ASSERT_TRUE(started) << "the run did not reach iteration 2";
  ASSERT_EQ(kill(pid, SIGINT), 0);
  bool exited = false;
  for (int wait = 0; wait < 600 && !exited; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    exited = kill(pid, 0) != 0 || IsZombie(pid);
  }
  ASSERT_TRUE(exited) << "ergo_optimize did not stop after SIGINT";
  ExpectCompleteOutputs(dir, false);
  const Json summary = ReadJsonFile(dir + "/summary.json");
  EXPECT_NE(GetString(summary, "stop_reason", "summary").find("interrupt"), std::string::npos);
  EXPECT_LE(GetNumber(summary, "optimized_score", "summary"),
            GetNumber(summary, "initial_score", "summary"));
  fs::remove_all(dir);
  fs::remove(log);
}

}  // namespace
}  // namespace ergo
