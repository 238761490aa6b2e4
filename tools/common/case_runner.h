// Runs one ergo_optimize process per case, N at a time, each in DIR/cases/<name>/ with its
// output in DIR/cases/<name>.log, each with --threads set so the cores are shared rather
// than oversubscribed. A case whose folder already holds a summary.json of a run that was
// not interrupted is kept, not run again, so a study stopped halfway resumes where it was.
// A failing case is reported (exit status and the log's last lines) and the others go on;
// SIGINT / SIGTERM (StopOnSignals, held by the caller) stop starting new cases.
//
//   CaseRunner runner(dir, ToolBesideThisProgram("ergo_optimize"), /*jobs=*/2, /*threads=*/0);
//   std::vector<CaseOutcome> outcomes = runner.Run(cases);   // in the order of `cases`
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ergo/mesh/json.h"

namespace ergo {

struct ToolCase {
  std::string name;                    // directory name under DIR/cases (safe characters)
  std::vector<std::string> arguments;  // ergo_optimize's flags; --threads and --out are added
};

struct CaseOutcome {
  bool finished = false;  // summary.json written and not interrupted
  bool kept = false;      // finished in an earlier run, not run again
  std::string failure;    // why not, one line with the log's path
  double seconds = 0;     // this run's wall time (0 for a kept case)
  Json summary;           // the case's summary.json when finished
};

// The program `name` (e.g. "ergo_optimize") in the folder of the running program (the
// build's bin/, or the install's).
std::string ToolBesideThisProgram(const std::string& name);

// True if DIR holds a readable summary.json of a run that was not interrupted.
bool CaseFinished(const std::filesystem::path& case_dir);

class CaseRunner {
 public:
  // Throws InputError naming --out or --ergo_optimize when the folder cannot be made or the
  // program is missing. threads = 0: the cores divided by jobs.
  CaseRunner(std::filesystem::path dir, std::string optimizer, int jobs, int threads);

  int threads_per_case() const { return threads_; }
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path CaseDir(const ToolCase& c) const { return dir_ / "cases" / c.name; }

  // Prints one line per case as it ends ("[3/8] 41.2 s  name: finished in 12.1 s").
  std::vector<CaseOutcome> Run(const std::vector<ToolCase>& cases) const;

 private:
  std::filesystem::path dir_;
  std::string optimizer_;
  int jobs_ = 1, threads_ = 1;
};

}  // namespace ergo
