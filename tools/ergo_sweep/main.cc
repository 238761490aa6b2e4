// ergo_sweep: a parameter study. Runs ergo_optimize once per case of the cartesian product
// of the --vary axes (any flag of ergo_optimize and its values), N cases at a time, each with
// --threads set so the cores are shared rather than oversubscribed, and collects the cases'
// fresh-placement results into DIR/sweep.csv, DIR/sweep.md and one picture per varied flag
// (DIR/sweep_<flag>.png). Each case writes DIR/cases/<case>/ (ergo_optimize's outputs) and
// DIR/cases/<case>.log. Run again over the same DIR, it keeps every case that finished (its
// summary.json is there and was not interrupted) and runs only the rest. A failing case is
// reported and the others go on.
//
//   ergo_sweep --flagfile=data/mouse.flags --vary=gamma_power=-3:1 --vary=exponent=2,3,4
//       --jobs=2 --out=sweep_mouse -- --max_evals=40
//
// Under `mpirun -np N ergo_sweep --mpi …` the cases are spread over the ranks (case i on
// rank i mod N, each rank running --jobs at a time with the cores of its machine shared
// among its ranks); rank 0 collects the outcomes and writes the reports. The case folders
// must be on a file system every rank sees (one machine, or a shared one).
//
// Flags after `--` are passed to every case. Exit status: 0 every case succeeded, 1 some case
// failed (sweep.md says which and why), 2 unusable input, 130 / 143 stopped by a signal
// (cases running then finish or stop with it; rerun the same command to resume).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "solvers/history_csv.h"
#include "tools/common/case_runner.h"
#include "tools/common/child_process.h"
#include "tools/common/flag_checks.h"
#include "tools/common/ranks.h"
#include "tools/common/run_signals.h"
#include "tools/common/sweep_plan.h"

DEFINE_int32(jobs, 1, "cases run at the same time");
DEFINE_int32(threads_per_job, 0, "--threads of each case; 0 = the cores divided by --jobs");
DEFINE_string(out, "", "sweep folder (required; created if missing, resumed if it holds cases)");
DEFINE_string(ergo_optimize, "", "the ergo_optimize to run; empty = the one beside ergo_sweep");
DEFINE_bool(plot, true, "write DIR/sweep_<flag>.png with tools/plot_sweep.py (matplotlib)");
DEFINE_bool(mpi, false,
            "spread the cases over the ranks of mpirun (mpirun -np N ergo_sweep --mpi)");

namespace ergo {
namespace {

namespace fs = std::filesystem;

// What the command line held for the cases: the --vary axes, the cases' --flagfile and the
// flags after `--`. Taken out before gflags sees the rest (gflags keeps only the last of a
// repeated flag, and the flagfile is ergo_optimize's, not this tool's).
struct SweepArguments {
  std::vector<SweepAxis> axes;
  std::string flagfile;
  std::vector<std::string> case_flags;
  std::vector<char*> rest;  // argv for gflags
};

// If argv[*i] is --NAME=VALUE or --NAME VALUE (one or two dashes), the value (advancing *i
// past a separate one); else nullopt.
std::optional<std::string> TakeValue(const std::string& name, int argc, char** argv, int* i) {
  const std::string argument = argv[*i];
  for (const std::string& flag : {"--" + name, "-" + name}) {
    if (argument.rfind(flag + "=", 0) == 0) return argument.substr(flag.size() + 1);
    if (argument == flag) {
      if (*i + 1 >= argc) throw InputError(flag, "", "has no value", "write " + flag + "=VALUE");
      return std::string(argv[++*i]);
    }
  }
  return std::nullopt;
}

SweepArguments SplitArguments(int argc, char** argv) {
  SweepArguments arguments;
  arguments.rest.push_back(argv[0]);
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--") {
      for (int k = i + 1; k < argc; ++k) arguments.case_flags.push_back(argv[k]);
      break;
    }
    if (const auto vary = TakeValue("vary", argc, argv, &i)) {
      arguments.axes.push_back(ParseSweepAxis(*vary));
    } else if (const auto flagfile = TakeValue("flagfile", argc, argv, &i)) {
      std::error_code error;
      if (!fs::is_regular_file(*flagfile, error))
        throw InputError("--flagfile", "", "'" + *flagfile + "' is not a readable file",
                         "give the cases' flagfile, e.g. data/shoe.flags");
      arguments.flagfile = fs::absolute(*flagfile).string();
    } else {
      arguments.rest.push_back(argv[i]);
    }
  }
  return arguments;
}

void ValidateAxes(const std::vector<SweepAxis>& axes) {
  if (axes.empty())
    throw InputError("--vary", "", "is required",
                     "e.g. --vary=gamma_power=-2:1 --vary=exponent=2,3");
  for (size_t a = 0; a < axes.size(); ++a) {
    const std::string& flag = axes[a].flag;
    for (const char* reserved : {"out", "threads", "flagfile", "resume"}) {
      if (flag == reserved)
        throw InputError("--vary", "", "--" + flag + " is set by the sweep for every case",
                         "vary another flag");
    }
    for (size_t b = 0; b < a; ++b) {
      if (axes[b].flag == flag)
        throw InputError("--vary", "", flag + " is varied twice", "give its values in one --vary");
    }
  }
}

// A case of the sweep: its plan and how it ended.
struct SweepOutcome {
  const SweepCase* plan = nullptr;
  CaseOutcome run;
};

double Field(const Json& summary, const char* key) {
  const Json* value = FindMember(summary, key);
  return value && value->is_number() ? value->get<double>() : std::nan("");
}

std::string Number(double value, int precision = 6) {
  if (!std::isfinite(value)) return "";
  std::ostringstream text;
  text << std::setprecision(precision) << value;
  return text.str();
}

// "12.3 %", or "—" where the run has no such figure (e.g. placement checks turned off).
std::string Percent(double value) { return std::isfinite(value) ? Number(value, 3) + " %" : "—"; }

// The columns of sweep.csv after the varied flags, and the summary.json keys they come from.
const std::vector<std::pair<const char*, const char*>> kColumns = {
    {"initial_score", "initial_score"},
    {"optimized_score", "optimized_score"},
    {"reduction_percent", "reduction_percent"},
    {"followed_reduction_percent", "followed_reduction_percent"},
    {"worst_placement_reduction_percent", "worst_placement_reduction_percent"},
    {"skin_zeta_reduction_percent", "skin_zeta_reduction_percent"},
    {"initial_peak_pressure_Pa", "initial_peak_pressure_Pa"},
    {"fresh_peak_pressure_Pa", "fresh_peak_pressure_Pa"},
    {"initial_plate_peak_pressure_Pa", "initial_plate_peak_pressure_Pa"},
    {"fresh_plate_peak_pressure_Pa", "fresh_plate_peak_pressure_Pa"},
    {"evaluations", "evaluations"},
    {"wall_s", "wall_s"}};

void WriteReports(const fs::path& dir, const std::vector<SweepAxis>& axes,
                  const std::vector<SweepOutcome>& outcomes) {
  WriteFileAtomically((dir / "sweep.csv").string(), [&](std::ostream& out) {
    out << "case";
    for (const SweepAxis& axis : axes) out << "," << CsvField(axis.flag);
    out << ",status";
    for (const auto& [column, key] : kColumns) out << "," << column;
    out << ",message\n";
    for (const SweepOutcome& o : outcomes) {
      out << CsvField(o.plan->name);
      for (const auto& [flag, value] : o.plan->flags) out << "," << CsvField(value);
      out << "," << (o.run.finished ? "ok" : "failed");
      for (const auto& [column, key] : kColumns)
        out << "," << (o.run.finished ? Number(Field(o.run.summary, key), 12) : "");
      out << "," << CsvField(o.run.failure) << "\n";
    }
  });
  WriteFileAtomically((dir / "sweep.md").string(), [&](std::ostream& out) {
    const long failed = std::count_if(outcomes.begin(), outcomes.end(),
                                      [](const SweepOutcome& o) { return !o.run.finished; });
    out << "# Sweep\n\n" << outcomes.size() << " cases";
    for (const SweepAxis& axis : axes) out << ", " << axis.flag << " × " << axis.values.size();
    out << "; " << outcomes.size() - failed << " finished, " << failed << " failed. Scores are "
        << "ergo_optimize's headline: the body placed afresh on the kept design.\n\n|";
    for (const SweepAxis& axis : axes) out << " " << axis.flag << " |";
    out << " reduction afresh | followed | worst placement | peak kPa before → after | "
           "5 mm plate's peak kPa before → after | evaluations | wall s |\n|";
    for (size_t k = 0; k < axes.size() + 7; ++k) out << "---|";
    out << "\n";
    for (const SweepOutcome& o : outcomes) {
      out << "|";
      for (const auto& [flag, value] : o.plan->flags) out << " " << value << " |";
      if (!o.run.finished) {
        out << " **failed** | | | | | | |\n";
        continue;
      }
      const Json& s = o.run.summary;
      out << " " << Percent(Field(s, "reduction_percent")) << " | "
          << Percent(Field(s, "followed_reduction_percent")) << " | "
          << Percent(Field(s, "worst_placement_reduction_percent")) << " | "
          << Number(Field(s, "initial_peak_pressure_Pa") / 1e3, 4) << " → "
          << Number(Field(s, "fresh_peak_pressure_Pa") / 1e3, 4) << " | "
          << Number(Field(s, "initial_plate_peak_pressure_Pa") / 1e3, 4) << " → "
          << Number(Field(s, "fresh_plate_peak_pressure_Pa") / 1e3, 4) << " | "
          << Number(Field(s, "evaluations")) << " | " << Number(Field(s, "wall_s"), 4) << " |\n";
    }
    if (failed > 0) {
      out << "\n## Failed cases\n\n";
      for (const SweepOutcome& o : outcomes) {
        if (!o.run.finished) out << "- `" << o.plan->name << "`: " << o.run.failure << "\n";
      }
    }
  });
}

void Plot(const fs::path& dir) { RunPictureScript("ergo_sweep", "plot_sweep.py", dir.string()); }

// An outcome as text, for the trip from a case's rank to rank 0.
Json OutcomeJson(size_t index, const CaseOutcome& o) {
  return {{"index", index},       {"finished", o.finished}, {"kept", o.kept},
          {"failure", o.failure}, {"seconds", o.seconds},   {"summary", o.summary}};
}

int Run(const SweepArguments& arguments, int argc, char** argv) {
  StopOnSignals signals;
  Ranks ranks(FLAGS_mpi, &argc, &argv, &StopOnSignals::flag());
  std::string error;
  std::unique_ptr<CaseRunner> runner;
  try {
    ValidateAxes(arguments.axes);
    if (FLAGS_out.empty()) throw InputError("--out", "", "is required", "give the sweep folder");
    RequireInRange("jobs", static_cast<long>(FLAGS_jobs), 1, 64, "e.g. 2");
    RequireInRange("threads_per_job", static_cast<long>(FLAGS_threads_per_job), 0, 1024,
                   "0 = the cores divided by --jobs");
    const std::string optimizer =
        FLAGS_ergo_optimize.empty() ? ToolBesideThisProgram("ergo_optimize") : FLAGS_ergo_optimize;
    // The ranks on one machine share its cores: each case gets cores / (jobs × ranks here).
    const int cores = std::max(1u, std::thread::hardware_concurrency());
    const int threads = FLAGS_threads_per_job > 0
                            ? FLAGS_threads_per_job
                            : std::max(1, cores / (FLAGS_jobs * ranks.local_size()));
    runner = std::make_unique<CaseRunner>(FLAGS_out, optimizer, FLAGS_jobs, threads);
  } catch (const InputError& e) {
    error = e.what();
  }
  error = ranks.FirstError(error);
  if (!error.empty()) {
    if (ranks.root()) std::cerr << "ergo_sweep: " << error << "\n";
    return 2;
  }
  const fs::path dir = runner->dir();

  const std::vector<SweepCase> cases = SweepCases(arguments.axes);
  std::vector<ToolCase> runs;
  std::vector<size_t> mine;  // this rank's cases
  for (size_t i = 0; i < cases.size(); ++i) {
    if (!ranks.Owns(static_cast<int>(i))) continue;
    const SweepCase& plan = cases[i];
    ToolCase run{plan.name, {}};
    if (!arguments.flagfile.empty()) run.arguments.push_back("--flagfile=" + arguments.flagfile);
    run.arguments.insert(run.arguments.end(), arguments.case_flags.begin(),
                         arguments.case_flags.end());
    for (const auto& [flag, value] : plan.flags) run.arguments.push_back("--" + flag + "=" + value);
    runs.push_back(std::move(run));
    mine.push_back(i);
  }
  std::cout << "ergo_sweep" << (ranks.mpi() ? " rank " + std::to_string(ranks.rank()) : "") << ": ";
  const std::vector<CaseOutcome> ran = runner->Run(runs);
  Json shipped = Json::array();
  for (size_t k = 0; k < mine.size(); ++k) shipped.push_back(OutcomeJson(mine[k], ran[k]));
  const std::vector<std::string> gathered = ranks.Gather(WriteJson(shipped, 0));
  const bool stopped = StopOnSignals::stopped();
  if (!ranks.root()) return stopped ? StopOnSignals::ExitCode() : 0;
  std::vector<CaseOutcome> all(cases.size());
  for (const std::string& text : gathered) {
    for (const Json& o : ParseJson(text, "a rank's outcomes")) {
      CaseOutcome& outcome = all[o["index"].get<size_t>()];
      outcome.finished = o["finished"].get<bool>();
      outcome.kept = o["kept"].get<bool>();
      outcome.failure = o["failure"].get<std::string>();
      outcome.seconds = o["seconds"].get<double>();
      outcome.summary = o["summary"];
    }
  }
  std::vector<SweepOutcome> outcomes(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) outcomes[i] = {&cases[i], all[i]};
  WriteReports(dir, arguments.axes, outcomes);
  if (FLAGS_plot) Plot(dir);
  const long failed = std::count_if(outcomes.begin(), outcomes.end(),
                                    [](const SweepOutcome& o) { return !o.run.finished; });
  std::cout << "ergo_sweep: " << cases.size() - failed << " of " << cases.size()
            << " cases finished"
            << (ranks.mpi() ? " on " + std::to_string(ranks.size()) + " ranks" : "") << "; wrote "
            << (dir / "sweep.csv").string() << ", sweep.md"
            << (FLAGS_plot ? " and the pictures" : "") << "\n";
  if (stopped) {
    std::cerr << "ergo_sweep: stopped by a signal; run the same command again to resume\n";
    return StopOnSignals::ExitCode();
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "a parameter sweep of ergo_optimize\n"
      "  ergo_sweep [--flagfile=data/SCENARIO.flags] --vary=NAME=V1,V2,...|NAME=A:B[:STEP] "
      "[--vary=...] [--jobs=N] --out=DIR [-- flags for every case]");
  ergo::SweepArguments arguments;
  try {
    arguments = ergo::SplitArguments(argc, argv);
    int rest_count = static_cast<int>(arguments.rest.size());
    ergo::CheckCommandLine(rest_count, arguments.rest.data());
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_sweep: " << error.what() << "\n";
    return 2;
  }
  int rest_count = static_cast<int>(arguments.rest.size());
  char** rest = arguments.rest.data();
  gflags::ParseCommandLineFlags(&rest_count, &rest, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run(arguments, argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_sweep: " << error.what() << "\n";
    return 2;
  }
}
