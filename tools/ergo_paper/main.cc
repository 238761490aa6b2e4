// ergo_paper: the paper's experiments (§5–§8) on ergo's chair, shoe and mouse scenes, by one
// command. Runs every optimisation the tables need as a separate ergo_optimize process (N at a
// time, resumable: a folder that holds finished runs keeps them), then writes
//   DIR/REPRODUCTION.md     the tables with the paper's figures beside them, and the pictures
//   DIR/table1.csv          flat and negative-image starts per scene (Table 1, Figs. 6, 8, 9)
//   DIR/table2.csv          the smoothing strength γ on the mouse (Table 2)
//   DIR/depth_sweep.csv     the chair's negative-image depth, 1–6 cm (§5.1)
//   DIR/exponents.csv       exponents 2, 3, 4 optimised on the shoe; bump_exponents.csv: Fig. 5
//   DIR/baselines.csv       Sit & Relax, Pose to Seat, ergo, ergo from Sit & Relax (§7, §8)
//   DIR/pressure_maps_<scene>.png  every design of a scene on one colour scale
//   DIR/cases/<run>/        each run's own outputs (ergo_optimize), and <run>.log
// Every score is the body placed afresh on the design.
//
//   ergo_paper --preset=quick --out=paper_quick          # minutes on 2 cores
//   ergo_paper --preset=paper --out=paper_full --jobs=1  # hours: the paper's resolutions
//   ergo_paper --preset=quick --experiments=table1,baselines --out=DIR -- --max_seconds=60
//
// Flags after `--` go to every run. Exit status: 0 every run finished, 1 some run failed
// (REPRODUCTION.md says which and why; its rows are marked), 2 unusable input, 130 / 143
// stopped by a signal (rerun the same command to resume).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/split_list.h"
#include "tools/common/case_runner.h"
#include "tools/common/child_process.h"
#include "tools/common/flag_checks.h"
#include "tools/common/paper_plan.h"
#include "tools/common/paper_report.h"
#include "tools/common/run_signals.h"

DEFINE_string(preset, "",
              "quick (the scenes' quick meshes, minutes) or paper (the paper's "
              "resolutions, hours); required");
DEFINE_string(out, "", "output folder (required; created if missing, resumed if it holds runs)");
DEFINE_string(experiments, "all",
              "comma-separated: table1, table2, depth_sweep, exponents, baselines; or all");
DEFINE_int32(jobs, 2, "runs at the same time");
DEFINE_int32(threads_per_job, 0, "--threads of each run; 0 = the cores divided by --jobs");
DEFINE_int32(max_evals, 0, "evaluations per optimisation; 0 = the preset's (quick 8, paper 20)");
DEFINE_int32(robust_placements, 0,
             "the objective's placements per run (1, 3 or 5); 0 = the preset's (1)");
DEFINE_bool(plot, true, "write the pictures with tools/plot_paper.py (matplotlib)");
DEFINE_string(ergo_optimize, "", "the ergo_optimize to run; empty = the one beside ergo_paper");
DEFINE_string(ergo_bump, "", "the ergo_bump to run (Fig. 5); empty = the one beside ergo_paper");

namespace ergo {
namespace {

namespace fs = std::filesystem;

std::set<std::string> Experiments() {
  if (FLAGS_experiments == "all") return {PaperExperiments().begin(), PaperExperiments().end()};
  std::set<std::string> chosen;
  for (const std::string& name : SplitList(FLAGS_experiments, ',')) chosen.insert(name);
  if (chosen.empty())
    throw InputError("--experiments", "", "is empty", "give all, or e.g. table1,baselines");
  return chosen;
}

PaperSettings Settings(const std::vector<std::string>& extra) {
  if (FLAGS_preset.empty())
    throw InputError("--preset", "", "is required", "give --preset=quick or --preset=paper");
  PaperSettings settings = DefaultPaperSettings(ParsePaperPreset(FLAGS_preset));
  RequireInRange("max_evals", static_cast<long>(FLAGS_max_evals), 0, 1000000, "0 = the preset's");
  if (FLAGS_max_evals > 0) settings.max_evals = FLAGS_max_evals;
  if (FLAGS_robust_placements != 0 && FLAGS_robust_placements != 1 &&
      FLAGS_robust_placements != 3 && FLAGS_robust_placements != 5)
    throw InputError("--robust_placements", "",
                     "is " + std::to_string(FLAGS_robust_placements) + "; it must be 1, 3 or 5",
                     "0 = the preset's");
  if (FLAGS_robust_placements > 0) settings.robust_placements = FLAGS_robust_placements;
  settings.extra = extra;
  return settings;
}

// The program a flag names, or the one beside ergo_paper.
std::string Program(const std::string& flag_value, const std::string& name) {
  return flag_value.empty() ? ToolBesideThisProgram(name) : flag_value;
}

// Fig. 5 by ergo_bump, into DIR/bump_exponents.csv (kept when a run before wrote it).
std::string RunBumpSweep(const fs::path& dir) {
  const fs::path csv = dir / "bump_exponents.csv";
  std::error_code error;
  if (fs::is_regular_file(csv, error)) return "";
  const std::vector<std::string> command = {Program(FLAGS_ergo_bump, "ergo_bump"),
                                            "--out=" + csv.string()};
  ChildOptions options;
  options.output = (dir / "cases" / "bump_exponents.log").string();
  const ChildProcessResult run = RunChildProcess(command, options);
  if (run.ok()) return "";
  return "ergo_bump " + run.Describe() + " (log: cases/bump_exponents.log)";
}

// The designs each scene's pressure-map picture shows, and which side of each run.
Json FigureManifest(const PaperPlan& plan, const CaseRunner& runner,
                    const std::vector<CaseOutcome>& outcomes) {
  Json scenes = Json::object();
  std::set<std::string> shown;
  auto add = [&](size_t i, const std::string& label, const char* side) {
    const PaperRun& run = plan.runs[i];
    const Json* failure =
        outcomes[i].finished ? FindMember(outcomes[i].summary, "kept_design_failure") : nullptr;
    if (!outcomes[i].finished || (failure && failure->is_string())) return;
    if (!shown.insert(run.scene + "/" + label).second) return;
    Json panel = Json::object();
    panel["label"] = label;
    panel["case"] = runner.CaseDir({run.Name(), {}}).string();
    panel["side"] = side;
    const Json* score = FindMember(
        outcomes[i].summary, std::string(side) == "initial" ? "initial_score" : "optimized_score");
    panel["score"] = score ? *score : Json();
    scenes[run.scene].push_back(panel);
  };
  std::vector<size_t> runs;
  for (const std::vector<size_t>* list : {&plan.table1, &plan.baselines})
    runs.insert(runs.end(), list->begin(), list->end());
  for (size_t i : runs) {
    const PaperRun& run = plan.runs[i];
    if (run.designer == "ergo" && run.start_designer == "none")
      add(i, run.negative_image ? "negative image" : "flat", "initial");
  }
  for (size_t i : runs) add(i, plan.runs[i].MethodLabel(), "optimized");
  Json manifest = Json::object();
  manifest["scenes"] = scenes;
  return manifest;
}

void Plot(const fs::path& dir) { RunPictureScript("ergo_paper", "plot_paper.py", dir.string()); }

std::string Today() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

std::string Reproduction(const PaperPlan& plan, const std::vector<PaperTable>& tables,
                         const std::vector<CaseOutcome>& outcomes, const std::string& command,
                         int threads, double wall_seconds, const std::string& bump_failure,
                         const fs::path& dir) {
  std::ostringstream md;
  const PaperSettings& s = plan.settings;
  double run_seconds = 0;
  int kept = 0, failed = 0;
  for (const CaseOutcome& o : outcomes) {
    // Each run's own wall time (summary.json), also for runs kept from an earlier invocation.
    const Json* wall = o.finished ? FindMember(o.summary, "wall_s") : nullptr;
    run_seconds += wall && wall->is_number() ? wall->get<double>() : o.seconds;
    kept += o.kept ? 1 : 0;
    failed += o.finished ? 0 : 1;
  }
  md << "# The paper's experiments on ergo's scenes (" << PaperPresetName(s.preset)
     << " preset)\n\n"
     << "Written by `" << command << "` on " << Today() << ", "
     << std::thread::hardware_concurrency() << " cores: " << plan.runs.size()
     << " ergo_optimize runs (" << kept << " kept from an earlier run of the same folder, "
     << failed << " failed), " << FLAGS_jobs << " at a time with --threads=" << threads
     << "; this invocation's wall time " << static_cast<long>(wall_seconds + 0.5)
     << " s, the runs' own optimisation times (summary.json wall_s) sum to "
     << static_cast<long>(run_seconds + 0.5) << " s.\n\n"
     << "Every run: the scene's flagfile (data/<scene>.flags) at --preset="
     << PaperPresetName(s.preset) << ", --max_evals=" << s.max_evals
     << ", --robust_placements=" << s.robust_placements
     << ", --placement_checks=" << (s.placement_checks ? "true" : "false");
  for (const std::string& flag : s.extra) md << ", " << flag;
  md << ". Every score is φ with the body placed afresh on the design (ergo_optimize's "
        "headline), never the optimiser's own path. Each run's outputs are in cases/<run>/ "
        "(summary.md, history.csv, the designs as STL/PLY/VTU).\n\n";
  for (const PaperTable& table : tables) {
    md << "## " << table.title << "\n\n"
       << table.note << " (`" << table.name << ".csv`)\n\n"
       << PaperMarkdown(table) << "\n";
    std::error_code error;
    if (table.name == "table2" && fs::exists(dir / "table2.png", error))
      md << "![γ sweep](table2.png)\n\n";
    if (table.name == "depth_sweep" && fs::exists(dir / "depth_sweep.png", error))
      md << "![depth sweep](depth_sweep.png)\n\n";
    if (table.name == "exponents") {
      md << (bump_failure.empty() ? "Fig. 5 (ζ against a bump's frequency, e = 2, 3, 4): "
                                    "`bump_exponents.csv`.\n\n"
                                  : "Fig. 5 was not computed: " + bump_failure + "\n\n");
    }
  }
  md << "## Pressure maps\n\nEach scene's designs, skin pressure seen from the support, on one "
        "colour scale per scene.\n\n";
  for (const char* scene : {"chair", "shoe", "mouse"}) {
    const std::string png = std::string("pressure_maps_") + scene + ".png";
    std::error_code error;
    if (fs::exists(dir / png, error)) md << "![" << scene << "](" << png << ")\n\n";
  }
  if (failed > 0) {
    md << "## Failed runs\n\n";
    for (size_t i = 0; i < outcomes.size(); ++i)
      if (!outcomes[i].finished)
        md << "- `" << plan.runs[i].Name() << "`: " << outcomes[i].failure << "\n";
  }
  return md.str();
}

// Flags after `--` are every run's; the rest are this tool's.
std::vector<std::string> SplitRunFlags(int* argc, char** argv) {
  std::vector<std::string> extra;
  for (int i = 1; i < *argc; ++i) {
    if (std::string(argv[i]) != "--") continue;
    for (int k = i + 1; k < *argc; ++k) extra.push_back(argv[k]);
    *argc = i;
    break;
  }
  return extra;
}

int Run(const std::vector<std::string>& extra, const std::string& command) {
  if (FLAGS_out.empty()) throw InputError("--out", "", "is required", "give the output folder");
  RequireInRange("jobs", static_cast<long>(FLAGS_jobs), 1, 64, "e.g. 2");
  RequireInRange("threads_per_job", static_cast<long>(FLAGS_threads_per_job), 0, 1024,
                 "0 = the cores divided by --jobs");
  const PaperPlan plan = MakePaperPlan(Settings(extra), Experiments());
  std::vector<ToolCase> cases;
  for (const PaperRun& run : plan.runs) {
    const std::string flagfile = DataFilePath(run.scene + ".flags");
    std::error_code error;
    if (!fs::is_regular_file(flagfile, error))
      throw InputError(flagfile, "", "the scene's flagfile is missing",
                       "run ergo_paper from a build of the source tree or an installed ergo");
    cases.push_back({run.Name(), run.Arguments(plan.settings, flagfile)});
  }
  const CaseRunner runner(FLAGS_out, Program(FLAGS_ergo_optimize, "ergo_optimize"), FLAGS_jobs,
                          FLAGS_threads_per_job);
  const fs::path dir = runner.dir();
  StopOnSignals signals;
  const auto begin = std::chrono::steady_clock::now();
  std::cout << "ergo_paper (" << FLAGS_preset << "): ";
  const std::vector<CaseOutcome> outcomes = runner.Run(cases);
  std::string bump_failure;
  if (plan.experiments.count("exponents") && !StopOnSignals::stopped()) {
    std::cout << "ergo_paper: Fig. 5 (ergo_bump)\n";
    bump_failure = RunBumpSweep(dir);
  }
  std::vector<Json> summaries;
  for (const CaseOutcome& o : outcomes) summaries.push_back(o.finished ? o.summary : Json());
  const std::vector<PaperTable> tables = PaperTables(plan, summaries);
  for (const PaperTable& table : tables)
    WritePaperCsv((dir / (table.name + ".csv")).string(), table);
  WriteJsonFile((dir / "figures.json").string(), FigureManifest(plan, runner, outcomes));
  if (FLAGS_plot && !StopOnSignals::stopped()) Plot(dir);
  const std::string md = Reproduction(plan, tables, outcomes, command, runner.threads_per_case(),
                                      SecondsSince(begin), bump_failure, dir);
  WriteFileAtomically((dir / "REPRODUCTION.md").string(), [&](std::ostream& out) { out << md; });
  const long failed = std::count_if(outcomes.begin(), outcomes.end(),
                                    [](const CaseOutcome& o) { return !o.finished; });
  std::cout << "ergo_paper: " << plan.runs.size() - failed << " of " << plan.runs.size()
            << " runs finished; wrote " << (dir / "REPRODUCTION.md").string() << " and "
            << tables.size() << " tables\n";
  if (StopOnSignals::stopped()) {
    std::cerr << "ergo_paper: stopped by a signal; run the same command again to resume\n";
    return StopOnSignals::ExitCode();
  }
  return failed > 0 || !bump_failure.empty() ? 1 : 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "the paper's tables on ergo's scenes\n"
      "  ergo_paper --preset=quick|paper --out=DIR [--experiments=table1,...] [--jobs=N] "
      "[-- flags for every run]");
  std::string command = "ergo_paper";
  for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  const std::vector<std::string> extra = ergo::SplitRunFlags(&argc, argv);
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_paper: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run(extra, command);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_paper: " << error.what() << "\n";
    return 2;
  }
}
