// ergo_sweep end to end on the bump scene: a 2 × 2 sweep, its reports, a resume that keeps
// the finished cases, and a failing case reported without stopping the others.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/test_paths.h"
#include "tests/support/text_files.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) { return testing::ReadTextFile(path.string()); }

using testing::CountLines;

struct Sweep {
  int status = -1;
  std::string output;
};

// A bump case costs about a second: two evaluations, one placement, no checks or pictures.
Sweep RunSweep(const fs::path& dir, const std::vector<std::string>& axes, bool plot,
               const std::vector<std::string>& launcher = {}) {
  std::vector<std::string> command = launcher;
  for (const char* part : {ERGO_BIN_DIR "/ergo_sweep", "--jobs=2"}) command.push_back(part);
  if (!launcher.empty()) command.push_back("--mpi");
  for (const std::string& part : std::vector<std::string>{
           "--out=" + dir.string(), std::string("--plot=") + (plot ? "true" : "false")})
    command.push_back(part);
  for (const std::string& axis : axes) command.push_back("--vary=" + axis);
  // One evaluation per case under the sanitizers (each then costs about ten times as much).
  for (const char* flag :
       {"--", "--scenario=bump", "--robust_placements=1", "--placement_checks=false",
        "--plot=false", "--round_evals=0", "--candidates=1"})
    command.push_back(flag);
  command.push_back(testing::SanitizedBuild() ? "--max_evals=1" : "--max_evals=2");
  ChildOptions options;
  options.output = dir.string() + ".out";
  const ChildProcessResult run = RunChildProcess(command, options);
  return {run.started && run.signal == 0 ? run.exit_code : -1, Read(options.output)};
}

TEST(ToolsSweep, TwoByTwoSweepWritesItsReportsAndResumesKeepingFinishedCases) {
  const fs::path dir = fs::path(testing::MakeScratchDir("sweep")) / "bump";
  const std::vector<std::string> axes = {"bump_height=0.002,0.004", "exponent=2,3"};
  const Sweep first = RunSweep(dir, axes, /*plot=*/true);
  ASSERT_EQ(first.status, 0) << first.output;
  const std::string csv = Read(dir / "sweep.csv");
  EXPECT_EQ(CountLines(csv), 5) << csv;  // header + 4 cases
  EXPECT_EQ(csv.rfind("case,bump_height,exponent,status,initial_score", 0), 0u) << csv;
  EXPECT_NE(csv.find("bump_height=0.004__exponent=3,0.004,3,ok,"), std::string::npos) << csv;
  const std::string md = Read(dir / "sweep.md");
  EXPECT_NE(md.find("4 cases, bump_height × 2, exponent × 2; 4 finished, 0 failed"),
            std::string::npos)
      << md;
  // The peak a 5 mm plate would read, before and after, beside ergo's per-vertex one.
  EXPECT_NE(csv.find(",initial_plate_peak_pressure_Pa,fresh_plate_peak_pressure_Pa,"),
            std::string::npos)
      << csv;
  EXPECT_NE(md.find("| 5 mm plate's peak kPa before → after |"), std::string::npos) << md;
  if (first.output.find("no python3 with matplotlib") == std::string::npos) {
    EXPECT_TRUE(fs::exists(dir / "sweep_bump_height.png")) << first.output;
    EXPECT_TRUE(fs::exists(dir / "sweep_exponent.png")) << first.output;
    // A result column is not taken for a varied flag.
    EXPECT_FALSE(fs::exists(dir / "sweep_fresh_plate_peak_pressure_Pa.png"));
  }

  // Half the folder gone (as if the sweep had been killed halfway): only that half runs.
  const fs::path kept = dir / "cases" / "bump_height=0.002__exponent=2" / "summary.json";
  const auto kept_time = fs::last_write_time(kept);
  fs::remove_all(dir / "cases" / "bump_height=0.004__exponent=2");
  fs::remove_all(dir / "cases" / "bump_height=0.004__exponent=3");
  const Sweep resumed = RunSweep(dir, axes, /*plot=*/false);
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("4 cases (2 finished before, kept), 2 to run"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(fs::last_write_time(kept), kept_time);  // not recomputed
  EXPECT_TRUE(fs::exists(dir / "cases" / "bump_height=0.004__exponent=3" / "summary.json"));
  EXPECT_EQ(CountLines(Read(dir / "sweep.csv")), 5);
}

TEST(ToolsSweep, AFailingCaseIsReportedAndTheOthersFinish) {
  const fs::path dir = fs::path(testing::MakeScratchDir("sweep_fail")) / "bump";
  // Exponent 7 is refused by ergo_optimize (2, 3 or 4): that case fails, exponent 3 runs.
  const Sweep run = RunSweep(dir, {"exponent=7,3"}, /*plot=*/false);
  EXPECT_EQ(run.status, 1) << run.output;
  const std::string md = Read(dir / "sweep.md");
  EXPECT_NE(md.find("2 cases, exponent × 2; 1 finished, 1 failed"), std::string::npos) << md;
  EXPECT_NE(md.find("## Failed cases"), std::string::npos) << md;
  EXPECT_NE(md.find("`exponent=7`: ergo_optimize exited 2"), std::string::npos) << md;
  EXPECT_NE(md.find("--exponent"), std::string::npos) << md;  // its own message, from the log
  EXPECT_TRUE(fs::exists(dir / "cases" / "exponent=3" / "summary.json"));
  EXPECT_NE(Read(dir / "sweep.csv").find("exponent=7,7,failed"), std::string::npos);
}

TEST(ToolsSweep, UnderMpirunTheCasesAreSpreadOverTheRanksAndReportedOnce) {
  if (testing::SanitizedBuild()) GTEST_SKIP() << "MPI is not built with the sanitizers";
  if (!fs::exists("/usr/bin/mpirun"))
    GTEST_SKIP() << "mpirun not found (apt-get install openmpi-bin)";
  const fs::path dir = fs::path(testing::MakeScratchDir("sweep_mpi")) / "bump";
  const Sweep run =
      RunSweep(dir, {"bump_height=0.002,0.003,0.004"}, /*plot=*/false,
               {"/usr/bin/mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"});
  ASSERT_EQ(run.status, 0) << run.output;
  // Case i ran on rank i mod 2 (each rank counts its own), rank 0 wrote the one report.
  EXPECT_NE(run.output.find("ergo_sweep rank 0: 2 cases"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("ergo_sweep rank 1: 1 case"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("3 of 3 cases finished on 2 ranks"), std::string::npos) << run.output;
  const std::string csv = Read(dir / "sweep.csv");
  EXPECT_EQ(CountLines(csv), 4) << csv;
  for (const char* height : {"0.002", "0.003", "0.004"})
    EXPECT_NE(csv.find(std::string("bump_height=") + height + "," + height + ",ok,"),
              std::string::npos)
        << csv;
}

TEST(ToolsSweep, BadSweepFlagsExitTwoNamingTheFlag) {
  const fs::path dir = fs::path(testing::MakeScratchDir("sweep_bad")) / "bump";
  for (const auto& [axes, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{}, "--vary: is required"},
           {{"out=a,b"}, "--out is set by the sweep"},
           {{"exponent=2,3", "exponent=4"}, "exponent is varied twice"},
           {{"exponent=1:9:0"}, "the step must be non-zero"}}) {
    const Sweep run = RunSweep(dir, axes, false);
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace ergo
