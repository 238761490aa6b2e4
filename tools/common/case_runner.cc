#include "tools/common/case_runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"
#include "tools/common/child_process.h"
#include "tools/common/run_signals.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// The last few non-empty lines of a case's log: where ergo_optimize says what went wrong.
std::string LogTail(const fs::path& log, int lines) {
  std::ifstream in(log);
  std::vector<std::string> kept;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    kept.push_back(line);
    if (static_cast<int>(kept.size()) > lines) kept.erase(kept.begin());
  }
  std::string text;
  for (const std::string& l : kept) text += (text.empty() ? "" : " / ") + l;
  return text;
}

std::string Seconds(double seconds) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << seconds;
  return text.str();
}

}  // namespace

std::string ToolBesideThisProgram(const std::string& name) {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return (self.parent_path() / name).string();
}

bool CaseFinished(const fs::path& case_dir) {
  std::error_code error;
  if (!fs::is_regular_file(case_dir / "summary.json", error)) return false;
  try {
    const Json summary = ReadJsonFile((case_dir / "summary.json").string());
    const Json* interrupted = FindMember(summary, "interrupted");
    return !(interrupted && interrupted->is_boolean() && interrupted->get<bool>());
  } catch (const InputError&) {
    return false;  // unreadable: run it again
  }
}

CaseRunner::CaseRunner(fs::path dir, std::string optimizer, int jobs, int threads)
    : dir_(fs::absolute(std::move(dir))), optimizer_(std::move(optimizer)), jobs_(jobs) {
  if (!fs::is_regular_file(optimizer_))
    throw InputError("--ergo_optimize", "", "'" + optimizer_ + "' is not there",
                     "build ergo_optimize, or give its path");
  std::error_code error;
  fs::create_directories(dir_ / "cases", error);
  if (error)
    throw InputError("--out", "", "'" + dir_.string() + "' cannot be created: " + error.message(),
                     "give a writable folder");
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  jobs_ = std::max(1, jobs_);
  threads_ = threads > 0 ? threads : std::max(1, cores / jobs_);
}

std::vector<CaseOutcome> CaseRunner::Run(const std::vector<ToolCase>& cases) const {
  std::vector<CaseOutcome> outcomes(cases.size());
  std::vector<size_t> pending;
  for (size_t i = 0; i < cases.size(); ++i) {
    if (CaseFinished(CaseDir(cases[i]))) {
      outcomes[i].finished = outcomes[i].kept = true;
    } else {
      pending.push_back(i);
    }
  }
  std::cout << cases.size() << " cases (" << cases.size() - pending.size()
            << " finished before, kept), " << pending.size() << " to run, " << jobs_
            << " at a time with --threads=" << threads_ << "\n";
  std::cout.flush();

  const auto begin = std::chrono::steady_clock::now();
  std::atomic<size_t> next{0};
  std::atomic<int> done{0};
  std::mutex print;
  auto worker = [&]() {
    for (size_t k; (k = next++) < pending.size() && !StopOnSignals::stopped();) {
      const ToolCase& plan = cases[pending[k]];
      CaseOutcome& outcome = outcomes[pending[k]];
      const fs::path case_dir = CaseDir(plan);
      std::vector<std::string> command = {optimizer_};
      command.insert(command.end(), plan.arguments.begin(), plan.arguments.end());
      command.push_back("--threads=" + std::to_string(threads_));
      command.push_back("--out=" + case_dir.string());
      ChildOptions options;
      options.output = (dir_ / "cases" / (plan.name + ".log")).string();
      const auto start = std::chrono::steady_clock::now();
      const ChildProcessResult run = RunChildProcess(command, options);
      outcome.seconds = SecondsSince(start);
      outcome.finished = run.ok() && CaseFinished(case_dir);
      if (!outcome.finished) {
        outcome.failure = "ergo_optimize " + run.Describe();
        const std::string tail = LogTail(options.output, 2);
        if (!tail.empty()) outcome.failure += ": " + tail;
        outcome.failure += " (log: cases/" + plan.name + ".log)";
      }
      std::lock_guard<std::mutex> lock(print);
      std::cout << "[" << ++done << "/" << pending.size() << "] " << Seconds(SecondsSince(begin))
                << " s  " << plan.name << ": "
                << (outcome.finished ? "finished in " + Seconds(outcome.seconds) + " s"
                                     : outcome.failure)
                << "\n";
      std::cout.flush();
    }
  };
  std::vector<std::thread> workers;
  for (int j = 0; j < jobs_; ++j) workers.emplace_back(worker);
  for (std::thread& w : workers) w.join();

  for (size_t i = 0; i < cases.size(); ++i) {
    CaseOutcome& outcome = outcomes[i];
    if (!outcome.finished) {
      if (outcome.failure.empty()) outcome.failure = "not run (stopped by a signal)";
      continue;
    }
    try {
      outcome.summary = ReadJsonFile((CaseDir(cases[i]) / "summary.json").string());
    } catch (const InputError& e) {
      outcome.finished = false;
      outcome.failure = e.what();
    }
  }
  return outcomes;
}

}  // namespace ergo
