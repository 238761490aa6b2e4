// The tools start their children (the plotting scripts) from an argument vector, never
// through a shell: an --out or flagfile value holding $( ), backticks, quotes, spaces or a
// newline is a directory name like any other — nothing in it runs, and the outputs land
// exactly where it says.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/test_paths.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// Values that a shell would execute: each touches a marker file if anything interprets it.
std::string Payload(const std::string& scratch, const std::string& tag) {
  return scratch + "/o_" + tag + "_$(touch " + scratch + "/PWNED_" + tag + ")_`touch " + scratch +
         "/PWNED_" + tag + "_b`_\"dq\"_'sq'_sp ace;touch " + scratch + "/PWNED_" + tag + "_c";
}

bool MatplotlibAvailable() { return !FindPythonWithMatplotlib().empty(); }

void ExpectNothingRan(const std::string& scratch) {
  for (const auto& entry : fs::directory_iterator(scratch))
    EXPECT_EQ(entry.path().filename().string().rfind("PWNED", 0), std::string::npos)
        << "a shell ran: " << entry.path();
  EXPECT_FALSE(fs::exists("PWNED")) << "a shell ran in the working directory";
}

// The tiny bump scene: a few evaluations take seconds.
std::vector<std::string> BumpRun(const std::string& tool) {
  return {std::string(ERGO_BIN_DIR) + "/" + tool, "--scenario=bump", "--bump_edge_length=0.02",
          "--max_evals=2", "--progress=false"};
}

TEST(ToolsNoShell, OptimizeOutputDirectoryIsNeverInterpreted) {
  const std::string scratch = testing::MakeScratchDir("noshell_optimize");
  const std::string out = Payload(scratch, "cli") + "\nnew line";
  std::vector<std::string> argv = BumpRun("ergo_optimize");
  argv.push_back("--out=" + out);
  const ChildProcessResult run = RunChildProcess(argv);
  ASSERT_TRUE(run.ok()) << run.Describe();
  ExpectNothingRan(scratch);
  EXPECT_TRUE(fs::exists(out + "/summary.json"));
  EXPECT_TRUE(fs::exists(out + "/support_optimized.stl"));
  if (MatplotlibAvailable()) {
    EXPECT_TRUE(fs::exists(out + "/pressure_maps.png"));
  }
  fs::remove_all(scratch);
}

TEST(ToolsNoShell, OptimizeFlagfileValueIsNeverInterpreted) {
  const std::string scratch = testing::MakeScratchDir("noshell_flagfile");
  const std::string out = Payload(scratch, "flagfile");  // a flagfile line holds no newline
  const std::string flagfile = scratch + "/scene.flags";
  {
    std::ofstream file(flagfile);
    file << "--scenario=bump\n--bump_edge_length=0.02\n--out=" << out << "\n";
  }
  const ChildProcessResult run =
      RunChildProcess({std::string(ERGO_BIN_DIR) + "/ergo_optimize", "--flagfile=" + flagfile,
                       "--max_evals=2", "--progress=false"});
  ASSERT_TRUE(run.ok()) << run.Describe();
  ExpectNothingRan(scratch);
  EXPECT_TRUE(fs::exists(out + "/summary.json"));
  if (MatplotlibAvailable()) {
    EXPECT_TRUE(fs::exists(out + "/phi_history.png"));
  }
  fs::remove_all(scratch);
}

TEST(ToolsNoShell, CompareOutputDirectoryIsNeverInterpreted) {
  const std::string scratch = testing::MakeScratchDir("noshell_compare");
  const std::string out = Payload(scratch, "compare") + "\nnew line";
  std::vector<std::string> argv = BumpRun("ergo_compare");
  argv.push_back("--optimizers=steepest");
  argv.push_back("--out=" + out);
  const ChildProcessResult run = RunChildProcess(argv);
  ASSERT_TRUE(run.ok()) << run.Describe();
  ExpectNothingRan(scratch);
  EXPECT_TRUE(fs::exists(out + "/compare.csv"));
  if (MatplotlibAvailable()) {
    EXPECT_TRUE(fs::exists(out + "/compare.png"));
  }
  fs::remove_all(scratch);
}

TEST(ToolsNoShell, ChildArgumentsArriveByteForByte) {
  // The child echoes its argument into a file; the bytes must be the ones given.
  const std::string scratch = testing::MakeScratchDir("noshell_echo");
  const std::string argument = "$(touch " + scratch + "/PWNED) `x` \"a\" 'b' c\nd";
  const ChildProcessResult run = RunChildProcess(
      {"/bin/sh", "-c", "printf %s \"$1\" > \"$2\"", "sh", argument, scratch + "/echo.txt"});
  ASSERT_TRUE(run.ok()) << run.Describe();
  std::ifstream in(scratch + "/echo.txt");
  const std::string echoed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(echoed, argument);
  ExpectNothingRan(scratch);
  const ChildProcessResult missing = RunChildProcess({scratch + "/no_such_program"});
  EXPECT_FALSE(missing.started);
  EXPECT_NE(missing.Describe().find("no_such_program"), std::string::npos) << missing.Describe();
  fs::remove_all(scratch);
}

}  // namespace
}  // namespace ergo
