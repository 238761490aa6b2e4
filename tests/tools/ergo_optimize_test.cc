// ergo_optimize end to end: a small budget lowers the score of the body placed afresh and
// writes every listed output with the summary's headline keys; SIGINT and SIGTERM leave
// complete outputs for the best design so far (exit 130 / 143); SIGKILL leaves the previous
// complete output or none, never a mixture, and the next run clears its temporaries; a run
// killed mid-way and resumed from its checkpoint ends bit for bit where an uninterrupted one
// ends.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "ergo/mesh/json.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/seconds_since.h"
#include "tests/support/test_paths.h"
#include "tests/support/text_files.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// The scenario the end-to-end test runs (the issue: the quick shoe sole).
const std::string kShoe = "--flagfile=" + testing::SourcePath("data/shoe.flags");

bool MatplotlibAvailable() { return !FindPythonWithMatplotlib().empty(); }

std::string Read(const std::string& path) { return testing::ReadTextFile(path); }

// history.csv: its header and its rows (no field of it is quoted).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int Column(const std::string& name) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  }
};

Csv ReadCsv(const std::string& path) {
  auto split = [](const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
  };
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (std::getline(in, line)) csv.header = split(line);
  while (std::getline(in, line)) csv.rows.push_back(split(line));
  return csv;
}

// The time split's entries (ergo/design/evaluation_timing.h) as history.csv's last columns and
// summary.json's time_split keys.
const std::vector<std::string> kTimeSplitSeconds = {
    "evaluation_s",    "support_s", "placement_s",   "predictor_s", "contact_s", "assembly_s",
    "factorization_s", "solve_s",   "line_search_s", "pressure_s",  "psi_s",     "adjoint_s"};
const std::vector<std::string> kTimeSplitCounts = {
    "equilibria",         "factorizations",         "pcg_iterations",
    "line_search_trials", "adjoint_factorizations", "adjoint_pcg_iterations",
    "fresh_placements"};

// history.csv keeps its first columns and appends the time split, cumulative (never
// decreasing) over the rows; summary.json's time_split holds the run's totals.
void ExpectTimeSplit(const std::string& dir) {
  const Csv csv = ReadCsv(dir + "/history.csv");
  const std::vector<std::string> first = {
      "iteration", "evaluations", "newton_iterations", "wall_s", "phi",
      "zeta",      "psi",         "grad_norm",         "step",   "kept_fresh_phi"};
  ASSERT_GE(csv.header.size(), first.size());
  EXPECT_EQ(std::vector<std::string>(csv.header.begin(), csv.header.begin() + first.size()), first);
  ASSERT_FALSE(csv.rows.empty());
  std::vector<std::string> cumulative = kTimeSplitSeconds;
  cumulative.insert(cumulative.end(), kTimeSplitCounts.begin(), kTimeSplitCounts.end());
  for (const std::string& name : cumulative) {
    const int column = csv.Column(name);
    ASSERT_GE(column, static_cast<int>(first.size())) << name;
    double previous = 0;
    for (const std::vector<std::string>& row : csv.rows) {
      ASSERT_EQ(row.size(), csv.header.size());
      const double value = std::stod(row[column]);
      EXPECT_GE(value, previous) << name;
      previous = value;
    }
  }
  ASSERT_GE(csv.Column("other_s"), 0);
  const Json summary = ReadJsonFile(dir + "/summary.json");
  const Json& split = GetMember(summary, "time_split", "summary");
  for (const std::string& name : cumulative) {
    EXPECT_GE(GetNumber(split, name, "time_split"), 0.0) << name;
    // The last history row is at most the run's total (evaluations after it: fresh checks).
    EXPECT_LE(std::stod(csv.rows.back()[csv.Column(name)]),
              GetNumber(split, name, "time_split") * (1 + 1e-12))
        << name;
  }
  EXPECT_NE(FindMember(split, "other_s"), nullptr);
  EXPECT_GT(GetNumber(split, "evaluation_s", "time_split"), 0.0);
  EXPECT_GT(GetNumber(split, "factorizations", "time_split"), 0.0);
  // One equilibrium per evaluation (one placement).
  EXPECT_EQ(GetNumber(split, "equilibria", "time_split"),
            GetNumber(summary, "evaluations", "summary"));

  // The runs are in fresh rounds: every row carries the kept design's score afresh, φ₀ at
  // the start, never rising, and never below the design finally kept (whose fresh check may
  // come after the last row). 1e-9: the CSV and the JSON print 17 significant digits.
  const int kept = csv.Column("kept_fresh_phi");
  const double initial = GetNumber(summary, "initial_score", "summary");
  const double optimized = GetNumber(summary, "optimized_score", "summary");
  EXPECT_NEAR(std::stod(csv.rows.front()[kept]), initial, 1e-9 * initial);
  double previous = initial;
  for (const std::vector<std::string>& row : csv.rows) {
    ASSERT_FALSE(row[kept].empty());
    const double value = std::stod(row[kept]);
    EXPECT_LE(value, previous * (1 + 1e-12));
    EXPECT_GE(value, optimized * (1 - 1e-9));
    previous = value;
  }
}

ChildProcessResult RunTool(std::vector<std::string> arguments, const std::string& log) {
  arguments.insert(arguments.begin(), std::string(ERGO_BIN_DIR) + "/ergo_optimize");
  ChildOptions options;
  options.output = log;
  return RunChildProcess(arguments, options);
}

void ExpectCompleteOutputs(const std::string& dir, bool pictures) {
  for (const char* file :
       {"summary.md", "summary.json", "history.csv", "support_initial.ply", "support_initial.stl",
        "support_optimized.ply", "support_optimized.stl", "body_initial.vtu", "body_optimized.vtu",
        "support_initial.vtu", "support_optimized.vtu", "plot_data.json"}) {
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
    const std::string text = Read(dir + "/" + file);
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

// The budget: 30 evaluations (5 under the sanitizers, 10-20x slower); the quick shoe with
// one placement is 53 % lower placed afresh after 5 evaluations (Release, 2026-12-02), so
// either clears the 20 % asserted.
constexpr int kShoeBudget = testing::SanitizedBuild() ? 5 : 30;

TEST(ToolsOptimize, QuickShoeLowersTheFreshScoreAndWritesEveryOutput) {
  const std::string dir = testing::MakeScratchDir("optimize") + "/out";
  // Under the sanitizers without the placement checks (16 more shoe equilibria, a third of
  // the run there; PlacementChecks has its own tests and the Release run covers them here).
  const bool sanitized = testing::SanitizedBuild();
  const ChildProcessResult run =
      RunTool({kShoe, "--max_evals=" + std::to_string(kShoeBudget), "--robust_placements=1",
               sanitized ? "--placement_checks=false" : "--placement_checks=true", "--out=" + dir},
              dir + ".log");
  ASSERT_TRUE(run.ok()) << run.Describe() << "\n" << Read(dir + ".log");
  const Json summary = ReadJsonFile(dir + "/summary.json");
  for (const char* key : {"initial_score",
                          "optimized_score",
                          "reduction_percent",
                          "followed_score",
                          "followed_reduction_percent",
                          "fresh_placement_converged",
                          "placement_checks",
                          "worst_placement_reduction_percent",
                          "skin_zeta",
                          "skin_zeta_reduction_percent",
                          "skin_contact_area_m2",
                          "fresh_peak_pressure_Pa",
                          "peak_relief_percent",
                          "offloading",
                          "contact_stiffness_Pa_per_m",
                          "filter_radius_m",
                          "gamma",
                          "wall_s",
                          "body_vertices",
                          "support_vertices",
                          "evaluations",
                          "time_split",
                          "stop_reason",
                          "candidates",
                          "centre_of_pressure",
                          "region_shares"}) {
    EXPECT_NE(FindMember(summary, key), nullptr) << key;
  }
  // The default load point, quiet standing's 0.445 of the foot's length from the heel: on the
  // flat sole every contact force is vertical, so the centre of pressure lies there (moment
  // balance; the torque uses the rest centre of mass, hence 0.01 as in the load-point tests).
  const double cop = summary["centre_of_pressure"]["initial"]["z_fraction"].get<double>();
  EXPECT_NEAR(cop, 0.445, 0.01);
  // The load's split on the flat sole, rearfoot / midfoot / forefoot, sums to one and keeps
  // the moment balance's order: the rearfoot, behind the centre of pressure, carries some.
  const Json& split = GetMember(summary, "region_shares", "summary");
  const Json& flat = GetMember(split, "initial", "region_shares");
  const double rear = GetNumber(flat, "rearfoot", "initial"),
               mid = GetNumber(flat, "midfoot", "initial"),
               fore = GetNumber(flat, "forefoot", "initial");
  EXPECT_NEAR(rear + mid + fore, 1.0, 1e-12);
  EXPECT_GT(rear, 0.2);
  EXPECT_GT(fore, 0.2);
  EXPECT_NE(Read(dir + "/summary.md").find("Load split rearfoot / midfoot / forefoot"),
            std::string::npos);
  // The generated foot at half body weight stays within its material law on the flat sole
  // (measured smallest principal stretch 0.286, the threshold 0.1), and summary.md says so.
  const Json& squeeze = GetMember(summary, "tissue_compression", "summary");
  const Json& squeezed = GetMember(squeeze, "initial", "tissue_compression");
  EXPECT_EQ(GetNumber(squeezed, "tets_beyond_inversion_threshold", "initial"), 0);
  EXPECT_GT(GetNumber(squeezed, "min_principal_stretch", "initial"), 0.1);
  EXPECT_LT(GetNumber(squeezed, "min_principal_stretch", "initial"), 1);
  EXPECT_NE(Read(dir + "/summary.md").find("0 tets on the initial design"), std::string::npos);
  // A 5 mm plate under the flat sole reads below ergo's per-vertex peak: its cells average the
  // peak's surroundings, and it divides by the stretched skin's area seen from below where ergo
  // divides by the rest area (measured 2026-12-07: about 140 kPa against 294 kPa).
  const double plate_initial = GetNumber(summary, "initial_plate_peak_pressure_Pa", "summary");
  EXPECT_GT(plate_initial, 0);
  EXPECT_LT(plate_initial, GetNumber(summary, "initial_peak_pressure_Pa", "summary"));
  EXPECT_GT(GetNumber(summary, "fresh_plate_peak_pressure_Pa", "summary"), 0);
  EXPECT_NE(Read(dir + "/summary.md").find("| peak a 5 mm plate reads (kPa) |"), std::string::npos);
  // The clinical criterion's thresholds are sensor readings, so it reads the plate's peak.
  const Json& offloading = GetMember(summary, "offloading", "summary");
  EXPECT_EQ(offloading["reading"].get<std::string>(), "5 mm plate");
  EXPECT_EQ(GetNumber(offloading, "initial_peak_Pa", "offloading"), plate_initial);
  EXPECT_NE(Read(dir + "/summary.md").find("on the peak a 5 mm plate reads:"), std::string::npos);
  // The pressure maps mark the same bands: contiguous along z from the heel, carrying the
  // summary's shares.
  const Json plot = ReadJsonFile(dir + "/plot_data.json");
  const Json& bands = GetMember(plot, "regions", "plot_data");
  // ... and mark every tet past the material's law (none here: see above).
  EXPECT_EQ(
      GetMember(GetMember(plot, "initial", "plot_data"), "crushed_points2d", "initial").size(),
      GetMember(squeezed, "tets_beyond_inversion_threshold", "initial").get<size_t>());
  ASSERT_EQ(bands.size(), 3u);
  EXPECT_EQ(bands[0]["name"].get<std::string>(), "rearfoot");
  for (size_t k = 1; k < bands.size(); ++k)
    EXPECT_EQ(bands[k]["v_from"].get<double>(), bands[k - 1]["v_to"].get<double>());
  EXPECT_LT(bands[0]["v_from"].get<double>(), bands[2]["v_to"].get<double>());
  EXPECT_EQ(bands[0]["initial_share"].get<double>(), rear);
  // The headline is the body placed afresh: the kept design must beat the flat sole there.
  EXPECT_TRUE(GetBool(summary, "fresh_placement_converged", "summary"));
  EXPECT_GE(GetNumber(summary, "reduction_percent", "summary"), 20.0) << Read(dir + ".log");
  EXPECT_LT(GetNumber(summary, "optimized_score", "summary"),
            GetNumber(summary, "initial_score", "summary"));
  EXPECT_LE(GetNumber(summary, "evaluations", "summary"), kShoeBudget);
  // Shoe checks: ±3 mm along both horizontal axes and ±1° of held roll, each with a verdict.
  const Json& checks = GetMember(summary, "placement_checks", "summary");
  EXPECT_EQ(checks.size(), sanitized ? 0u : 6u);
  for (size_t i = 0; i < checks.size(); ++i) {
    EXPECT_TRUE(GetBool(checks[i], "converged", "check"));
    EXPECT_NE(FindMember(checks[i], "reduction_percent"), nullptr);
  }
  const Json& skin = GetMember(summary, "skin_zeta", "summary");
  EXPECT_LT(GetNumber(skin, "fresh", "skin_zeta"), GetNumber(skin, "initial", "skin_zeta"));
  ExpectTimeSplit(dir);
  ExpectCompleteOutputs(dir, MatplotlibAvailable());
  fs::remove_all(fs::path(dir).parent_path());
}

// Starts ergo_optimize in the background and returns its pid; `log` collects its output.
pid_t Start(const std::vector<std::string>& arguments, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<std::string> argv = {std::string(ERGO_BIN_DIR) + "/ergo_optimize"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    std::vector<char*> args;
    for (std::string& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    std::freopen(log.c_str(), "w", stdout);
    dup2(fileno(stdout), STDERR_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// Waits until `log` holds `text` (or the process ended); false on a timeout of `seconds`.
bool WaitFor(pid_t pid, const std::string& log, const std::string& text, double seconds) {
  const auto begin = std::chrono::steady_clock::now();
  while (SecondsSince(begin) < seconds) {
    if (Read(log).find(text) != std::string::npos) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

int WaitForExit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

class ToolsOptimizeSignals : public ::testing::TestWithParam<int> {};

TEST_P(ToolsOptimizeSignals, AStopSignalLeavesCompleteOutputsForTheBestDesign) {
  const int signal = GetParam();
  const std::string dir = testing::MakeScratchDir("signal") + "/out";
  const pid_t pid = Start({kShoe, "--max_evals=100000", "--robust_placements=1", "--plot=false",
                           "--placement_checks=false", "--out=" + dir},
                          dir + ".log");
  ASSERT_TRUE(WaitFor(pid, dir + ".log", "iter    2", 600)) << Read(dir + ".log");
  ASSERT_EQ(kill(pid, signal), 0);
  EXPECT_EQ(WaitForExit(pid), 128 + signal) << Read(dir + ".log");
  ExpectCompleteOutputs(dir, false);
  const Json summary = ReadJsonFile(dir + "/summary.json");
  EXPECT_TRUE(GetBool(summary, "interrupted", "summary"));
  EXPECT_NE(GetString(summary, "stop_reason", "summary").find("interrupt"), std::string::npos);
  EXPECT_LE(GetNumber(summary, "optimized_score", "summary"),
            GetNumber(summary, "initial_score", "summary"));
  fs::remove_all(fs::path(dir).parent_path());
}

INSTANTIATE_TEST_SUITE_P(Signals, ToolsOptimizeSignals, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) {
                           return info.param == SIGINT ? "sigint" : "sigterm";
                         });

// The bump scene: 40 evaluations in rounds of 8 take about ten seconds and checkpoint after
// every round (12 in rounds of 4 under the sanitizers, 10-20x slower: still two rounds to
// resume into after the first checkpoint).
std::vector<std::string> BumpRun(const std::string& out) {
  const bool sanitized = testing::SanitizedBuild();
  return {"--scenario=bump",
          "--bump_edge_length=0.01",
          sanitized ? "--max_evals=12" : "--max_evals=40",
          sanitized ? "--round_evals=4" : "--round_evals=8",
          "--candidates=2",
          "--plot=false",
          "--placement_checks=false",
          "--progress=true",
          "--out=" + out};
}

TEST(ToolsOptimize, AKilledRunLeavesThePreviousOutputOrNoneAndResumesToTheSameDesign) {
  const std::string scratch = testing::MakeScratchDir("resume");
  // The uninterrupted run.
  const std::string whole = scratch + "/whole";
  ASSERT_TRUE(RunTool(BumpRun(whole), whole + ".log").ok()) << Read(whole + ".log");
  const Json reference = ReadJsonFile(whole + "/summary.json");

  // A previous complete output in place, then a run into the same directory killed after
  // its first checkpoint.
  const std::string dir = scratch + "/killed";
  ASSERT_TRUE(RunTool({"--scenario=bump", "--bump_edge_length=0.01", "--max_evals=3",
                       "--plot=false", "--placement_checks=false", "--out=" + dir},
                      dir + ".first.log")
                  .ok());
  const std::string previous = Read(dir + "/summary.json");
  const pid_t pid = Start(BumpRun(dir), dir + ".log");
  bool checkpointed = false;
  for (int wait = 0; wait < 6000 && !checkpointed; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    checkpointed = fs::exists(dir + ".checkpoint.json");
  }
  ASSERT_TRUE(checkpointed) << Read(dir + ".log");
  ASSERT_EQ(waitpid(pid, nullptr, WNOHANG), 0) << "the run ended before it could be killed";
  kill(pid, SIGKILL);
  WaitForExit(pid);
  // Either the previous complete output or none: here the previous one, untouched.
  ASSERT_TRUE(fs::exists(dir + "/summary.json"));
  EXPECT_TRUE(Read(dir + "/summary.json") == previous) << "the previous output was changed";
  bool temporary = false;
  for (const auto& entry : fs::directory_iterator(scratch))
    temporary |= entry.path().filename().string().find("killed.tmp-") != std::string::npos;
  EXPECT_TRUE(temporary) << "the killed run's temporary directory should be left to clean";

  // Resumed: the same design and score as the uninterrupted run, bit for bit.
  ASSERT_TRUE(RunTool({"--resume=" + dir}, dir + ".resume.log").ok()) << Read(dir + ".resume.log");
  EXPECT_NE(Read(dir + ".resume.log").find("resuming after round"), std::string::npos);
  const Json resumed = ReadJsonFile(dir + "/summary.json");
  EXPECT_EQ(GetNumber(resumed, "optimized_score", "resumed"),
            GetNumber(reference, "optimized_score", "reference"));
  EXPECT_EQ(GetNumber(resumed, "evaluations", "resumed"),
            GetNumber(reference, "evaluations", "reference"));
  // The time split's counts run on through the checkpoint (its seconds are this machine's).
  for (const char* count : {"equilibria", "factorizations", "line_search_trials"}) {
    EXPECT_EQ(GetNumber(GetMember(resumed, "time_split", "resumed"), count, "resumed"),
              GetNumber(GetMember(reference, "time_split", "reference"), count, "reference"))
        << count;
  }
  ExpectTimeSplit(dir);
  EXPECT_TRUE(Read(dir + "/support_optimized.ply") == Read(whole + "/support_optimized.ply"))
      << "the resumed design differs from the uninterrupted one";
  // The resumed run cleared the stale temporary and, complete, its checkpoint.
  for (const auto& entry : fs::directory_iterator(scratch))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  EXPECT_FALSE(fs::exists(dir + ".checkpoint.json"));
  fs::remove_all(scratch);
}

// A time budget given alone is the whole budget (no 40-evaluation default under it); with
// --max_evals too, both hold.
TEST(ToolsOptimize, ATimeBudgetAloneHasNoEvaluationCap) {
  const std::string dir = testing::MakeScratchDir("time_budget");
  const std::vector<std::string> common = {"--scenario=bump", "--bump_edge_length=0.01",
                                           "--robust_placements=1", "--plot=false",
                                           "--placement_checks=false"};
  std::vector<std::string> alone = common;
  alone.insert(alone.end(), {"--max_seconds=0.5", "--out=" + dir + "/alone"});
  ASSERT_TRUE(RunTool(alone, dir + "/alone.log").ok()) << Read(dir + "/alone.log");
  EXPECT_NE(Read(dir + "/alone.log").find("budget: no evaluation cap, 0.5 s wall"),
            std::string::npos)
      << Read(dir + "/alone.log");
  std::vector<std::string> both = common;
  both.insert(both.end(), {"--max_seconds=100", "--max_evals=3", "--out=" + dir + "/both"});
  ASSERT_TRUE(RunTool(both, dir + "/both.log").ok()) << Read(dir + "/both.log");
  EXPECT_NE(Read(dir + "/both.log").find("budget: 3 evaluations, 100 s wall"), std::string::npos)
      << Read(dir + "/both.log");
  EXPECT_LE(GetNumber(ReadJsonFile(dir + "/both/summary.json"), "evaluations", "summary"), 3.0);
  std::vector<std::string> neither = common;
  neither.insert(neither.end(), {"--max_evals=2", "--out=" + dir + "/evals"});
  ASSERT_TRUE(RunTool(neither, dir + "/evals.log").ok()) << Read(dir + "/evals.log");
  EXPECT_NE(Read(dir + "/evals.log").find("budget: 2 evaluations\n"), std::string::npos)
      << Read(dir + "/evals.log");
  fs::remove_all(dir);
}

// --support_model=soft: the bump plate becomes foam, the design moves its rest shape, and the
// optimised rest shape is the printed part; the summary says which support model ran.
TEST(ToolsOptimize, ASoftSupportsRestShapeIsOptimised) {
  const std::string dir = testing::MakeScratchDir("soft_optimize");
  const std::vector<std::string> args = {"--scenario=bump",
                                         "--bump_edge_length=0.015",
                                         "--robust_placements=1",
                                         "--plot=false",
                                         "--placement_checks=false",
                                         "--max_evals=4",
                                         "--support_model=soft",
                                         "--support_youngs_modulus=5e4",
                                         "--soft_support_edge_length=0.01",
                                         "--soft_support_base_edge_length=0.02",
                                         "--out=" + dir + "/soft"};
  ASSERT_TRUE(RunTool(args, dir + "/soft.log").ok()) << Read(dir + "/soft.log");
  const Json summary = ReadJsonFile(dir + "/soft/summary.json");
  EXPECT_GT(GetNumber(summary, "evaluations", "summary"), 0.0);
  EXPECT_TRUE(fs::exists(dir + "/soft/support_optimized.stl"));
  // The foam's solid at both designs, deformed under the body, with its stress and strain.
  for (const char* tag : {"initial", "optimized"}) {
    const std::string solid = Read(dir + "/soft/support_solid_" + tag + ".vtu");
    EXPECT_NE(solid.find("von_mises_stress_Pa"), std::string::npos) << tag;
    EXPECT_NE(solid.find("volume_change"), std::string::npos) << tag;
    EXPECT_NE(Read(dir + "/soft/support_" + tag + ".vtu").find("displacement_m"), std::string::npos)
        << tag;
  }
  EXPECT_NE(Read(dir + "/soft.log").find("soft support"), std::string::npos)
      << Read(dir + "/soft.log");
  fs::remove_all(dir);
}

// The default optimiser is nlopt-lbfgs, ceres-lbfgs at the paper presets (the paper-resolution
// comparison in the README), and what --optimizer names in either case.
TEST(ToolsOptimize, ThePaperPresetDefaultsToCeresLbfgsUnlessAnOptimizerIsNamed) {
  const std::string dir = testing::MakeScratchDir("default_optimizer");
  const std::vector<std::string> common = {"--scenario=bump",          "--bump_edge_length=0.01",
                                           "--robust_placements=1",    "--plot=false",
                                           "--placement_checks=false", "--max_evals=2"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "nlopt-lbfgs"},
      {{"--preset=paper"}, "ceres-lbfgs"},
      {{"--preset=paper", "--optimizer=nlopt-mma"}, "nlopt-mma"}};
  for (size_t i = 0; i < cases.size(); ++i) {
    std::vector<std::string> arguments = common;
    arguments.insert(arguments.end(), cases[i].first.begin(), cases[i].first.end());
    const std::string out = dir + "/" + std::to_string(i);
    arguments.push_back("--out=" + out);
    ASSERT_TRUE(RunTool(arguments, out + ".log").ok()) << Read(out + ".log");
    EXPECT_EQ(GetString(ReadJsonFile(out + "/summary.json"), "optimizer", "summary"),
              cases[i].second);
  }
  fs::remove_all(dir);
}

TEST(ToolsOptimize, GeometricBaselinesAreScoredAndWrittenLikeAnyDesign) {
  const std::string dir = testing::MakeScratchDir("baseline");
  for (const std::string designer : {"sit-and-relax", "pose-to-seat"}) {
    const std::string out = dir + "/" + designer;
    const ChildProcessResult run =
        RunTool({"--scenario=bump", "--designer=" + designer, "--robust_placements=1",
                 "--placement_checks=false", "--plot=false", "--out=" + out},
                out + ".log");
    ASSERT_TRUE(run.ok()) << run.Describe() << "\n" << Read(out + ".log");
    ExpectCompleteOutputs(out, /*pictures=*/false);
    const Json summary = ReadJsonFile(out + "/summary.json");
    EXPECT_EQ(GetString(summary, "optimizer", "summary"), designer);
    EXPECT_EQ(GetNumber(summary, "evaluations", "summary"), 1);  // no optimiser ran
    // The headline is the body placed afresh on the baseline's support; the bump's peak is
    // what both baselines relieve first (the ball rests on it), so they score below the flat
    // start — the paper's baselines are no straw men.
    const double reduction = GetNumber(summary, "reduction_percent", "summary");
    EXPECT_GT(reduction, 0) << designer;
    EXPECT_NE(Read(out + ".log").find(designer + ": "), std::string::npos);
  }
  const ChildProcessResult bad =
      RunTool({"--scenario=bump", "--designer=by-hand", "--out=" + dir + "/bad"}, dir + "/bad.log");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(Read(dir + "/bad.log").find("--designer"), std::string::npos);
  const ChildProcessResult both =
      RunTool({"--scenario=bump", "--designer=pose-to-seat", "--start_designer=sit-and-relax",
               "--out=" + dir + "/both"},
              dir + "/both.log");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(Read(dir + "/both.log").find("--start_designer"), std::string::npos);
}

// ergo started from the Sit & Relax surface (paper §7): the optimiser's start is exactly the
// baseline's design (its fresh score is the one the baseline run reports), the kept design
// is no worse than that start, and scores stay relative to the scene's flat support.
TEST(ToolsOptimize, ErgoStartedFromABaselineStartsAtItsDesign) {
  const std::string dir = testing::MakeScratchDir("start_designer");
  const std::vector<std::string> common = {"--scenario=bump", "--robust_placements=1",
                                           "--placement_checks=false", "--plot=false"};
  std::vector<std::string> baseline = common, from = common;
  baseline.insert(baseline.end(), {"--designer=sit-and-relax", "--out=" + dir + "/baseline"});
  from.insert(from.end(), {"--start_designer=sit-and-relax", "--max_evals=6", "--round_evals=0",
                           "--out=" + dir + "/from"});
  ASSERT_TRUE(RunTool(baseline, dir + "/baseline.log").ok()) << Read(dir + "/baseline.log");
  ASSERT_TRUE(RunTool(from, dir + "/from.log").ok()) << Read(dir + "/from.log");
  const Json b = ReadJsonFile(dir + "/baseline/summary.json");
  const Json f = ReadJsonFile(dir + "/from/summary.json");
  EXPECT_EQ(GetString(f, "start", "summary"), "sit-and-relax");
  EXPECT_EQ(GetString(b, "start", "summary"), "initial");
  // Same design, same fresh placement, same threads' reduction order: the same number.
  EXPECT_NEAR(GetNumber(f, "start_score", "summary"), GetNumber(b, "optimized_score", "summary"),
              1e-9 * GetNumber(b, "optimized_score", "summary"));
  EXPECT_DOUBLE_EQ(GetNumber(f, "initial_score", "summary"),
                   GetNumber(b, "initial_score", "summary"));  // both against the flat plate
  EXPECT_LE(GetNumber(f, "optimized_score", "summary"),
            GetNumber(f, "start_score", "summary") * (1 + 1e-12));
  EXPECT_NE(Read(dir + "/from/summary.md").find("started from the sit-and-relax design"),
            std::string::npos);
}

}  // namespace
}  // namespace ergo
