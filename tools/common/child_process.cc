#include "tools/common/child_process.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace ergo {

std::string ChildProcessResult::Describe() const {
  if (!started) return "could not be started: " + error;
  if (signal != 0)
    return "was ended by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  return "exited " + std::to_string(exit_code);
}

ChildProcessResult RunChildProcess(const std::vector<std::string>& argv, bool quiet) {
  ChildOptions options;
  options.quiet = quiet;
  return RunChildProcess(argv, options);
}

ChildProcessResult RunChildProcess(const std::vector<std::string>& argv,
                                   const ChildOptions& options) {
  ChildProcessResult result;
  if (argv.empty() || argv[0].empty()) {
    result.error = "no program given";
    return result;
  }
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (options.quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  } else if (!options.output.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, options.output.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  if (!options.working_directory.empty())
    posix_spawn_file_actions_addchdir_np(&actions, options.working_directory.c_str());
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    result.error = argv[0] + ": " + std::strerror(spawned);
    return result;
  }
  result.started = true;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      result.error = std::string("waitpid: ") + std::strerror(errno);
      result.started = false;
      return result;
    }
  }
  if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  return result;
}

std::string CommandLineForDisplay(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& arg : argv) {
    if (!line.empty()) line += ' ';
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789_-./=:,+@%") == std::string::npos;
    if (plain) {
      line += arg;
      continue;
    }
    line += '\'';
    for (char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

namespace {

// <prefix>/share/ergo/<folder>/<name> beside the running program, if it exists; else "".
std::string InstalledFile(const std::string& folder, const std::string& name) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return "";
  const std::filesystem::path installed =
      self.parent_path().parent_path() / "share" / "ergo" / folder / name;
  return std::filesystem::exists(installed, error) ? installed.string() : "";
}

}  // namespace

std::string ToolScriptPath(const std::string& name) {
  const std::string installed = InstalledFile("tools", name);
  return installed.empty() ? std::string(ERGO_TOOLS_DIR) + "/" + name : installed;
}

std::string DataFilePath(const std::string& name) {
  const std::string installed = InstalledFile("data", name);
  if (!installed.empty()) return installed;
  return (std::filesystem::path(ERGO_TOOLS_DIR) / ".." / "data" / name).lexically_normal().string();
}

std::string FindPythonWithMatplotlib(const std::string& preferred) {
  const std::vector<std::string> candidates =
      preferred.empty() ? std::vector<std::string>{"python3", "/usr/bin/python3"}
                        : std::vector<std::string>{preferred};
  for (const std::string& python : candidates) {
    if (RunChildProcess({python, "-c", "import matplotlib"}, /*quiet=*/true).ok()) return python;
  }
  return "";
}

bool RunPictureScript(const std::string& tool, const std::string& script, const std::string& dir) {
  const std::string python = FindPythonWithMatplotlib();
  if (python.empty()) {
    std::cerr << tool
              << ": warning: pictures not written: no python3 with matplotlib found "
                 "(Debian: apt-get install python3-matplotlib)\n";
    return false;
  }
  // An argument vector, never a shell: the folder may hold any character.
  const std::vector<std::string> command = {python, ToolScriptPath(script), dir};
  const ChildProcessResult plotted = RunChildProcess(command);
  if (!plotted.ok())
    std::cerr << tool << ": warning: pictures not written: " << CommandLineForDisplay(command)
              << " " << plotted.Describe() << "\n";
  return plotted.ok();
}

}  // namespace ergo
