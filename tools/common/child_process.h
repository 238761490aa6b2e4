// Child processes of the tools (the plotting scripts): started from an argument vector with
// posix_spawnp and never through a shell, so a path or flag value is passed to the child as
// the bytes it is — `$( )`, backticks, quotes, spaces and newlines included — and nothing in
// it is ever interpreted as a command.
#pragma once

#include <string>
#include <vector>

namespace ergo {

struct ChildProcessResult {
  bool started = false;  // false: the program could not be started (see error)
  int exit_code = -1;    // the exit status when it exited normally
  int signal = 0;        // the signal that ended it, 0 if none
  std::string error;     // why it did not start
  bool ok() const { return started && signal == 0 && exit_code == 0; }
  // "exited 1", "was ended by signal 2 (Interrupt)", "could not be started: ...".
  std::string Describe() const;
};

struct ChildOptions {
  bool quiet = false;             // stdout and stderr to /dev/null
  std::string output;             // else, if set: stdout and stderr into this file
  std::string working_directory;  // if set: the child starts there
};

// Runs argv[0] (looked up on PATH when it holds no '/') with exactly these arguments, waits
// for it and returns how it ended.
ChildProcessResult RunChildProcess(const std::vector<std::string>& argv,
                                   const ChildOptions& options);
// The same, `quiet` sending its stdout and stderr to /dev/null.
ChildProcessResult RunChildProcess(const std::vector<std::string>& argv, bool quiet = false);

// The command line as a user would type it, each argument single-quoted where needed: for
// messages only (it is never executed).
std::string CommandLineForDisplay(const std::vector<std::string>& argv);

// The first Python that can import matplotlib: `preferred` if not empty (and only it), else
// python3 on the PATH, else Debian's /usr/bin/python3 (where python3-matplotlib installs; a
// pyenv or venv python3 earlier on the PATH may lack it). "" if none.
std::string FindPythonWithMatplotlib(const std::string& preferred = "");

// A helper script of the tools (e.g. "plot_results.py"): next to an installed tool
// (<prefix>/share/ergo/tools/, `cmake --install`) when it is there, else in the source
// tree the tool was built from.
std::string ToolScriptPath(const std::string& name);

// Runs the picture script `script` (ToolScriptPath) on `dir` with the first Python that has
// matplotlib. A missing matplotlib or a failing script is a warning on stderr prefixed by
// `tool` ("ergo_sweep: warning: ..."), never an error: the numbers are written already.
// Returns whether the pictures were written.
bool RunPictureScript(const std::string& tool, const std::string& script, const std::string& dir);

// A file shipped with ergo's data (e.g. "chair.flags", a scene's flagfile): in
// <prefix>/share/ergo/data/ beside an installed tool when it is there, else in the source
// tree's data/.
std::string DataFilePath(const std::string& name);

}  // namespace ergo
