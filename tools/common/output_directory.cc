#include "tools/common/output_directory.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// The pid in a sibling's name "<base>.<tag>-<pid>", or -1.
long SiblingPid(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0) return -1;
  const std::string digits = name.substr(prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(digits);
}

bool Alive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

}  // namespace

OutputDirectory::OutputDirectory(const std::string& final_path, const std::string& flag) {
  if (final_path.empty()) throw InputError(flag, "", "is empty", "give a directory, e.g. ergo_out");
  std::error_code ec;
  const fs::path target = fs::absolute(fs::path(final_path), ec).lexically_normal();
  const std::string text = target.string();
  for (const char* system : {"/proc", "/sys", "/dev"}) {
    const std::string root(system);
    if (text == root || text.rfind(root + "/", 0) == 0) {
      throw InputError(flag, "", "'" + final_path + "' lies under " + root + ", not a place for files",
                       "write the outputs to a directory of your own");
    }
  }
  if (fs::exists(target, ec) && !fs::is_directory(target, ec)) {
    throw InputError(flag, "", "'" + final_path + "' exists and is not a directory",
                     "give a directory path, or move the file away");
  }
  fs::path parent = target.parent_path();
  if (parent.empty()) parent = ".";
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent) || ::access(parent.c_str(), W_OK | X_OK) != 0) {
    throw InputError(flag, "",
                     "cannot write into '" + parent.string() + "'" +
                         (ec ? " (" + ec.message() + ")" : std::string(" (permission denied)")),
                     "choose a writable directory");
  }
  final_ = target.string();
  const std::string base = target.filename().string();
  // A previous run killed between its two renames left its output as DIR.old-PID: restore it.
  // Temporaries of runs that are no longer alive go.
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    const long tmp_pid = SiblingPid(name, base + ".tmp-");
    const long old_pid = SiblingPid(name, base + ".old-");
    if (tmp_pid > 0 && !Alive(tmp_pid)) fs::remove_all(entry.path(), ec);
    if (old_pid > 0 && !Alive(old_pid)) {
      if (!fs::exists(target)) {
        fs::rename(entry.path(), target, ec);
      } else {
        fs::remove_all(entry.path(), ec);
      }
    }
  }
  temporary_ = (parent / (base + ".tmp-" + std::to_string(::getpid()))).string();
  fs::remove_all(temporary_, ec);
  if (!fs::create_directory(temporary_, ec) || ec) {
    throw InputError(flag, "", "cannot create '" + temporary_ + "' (" + ec.message() + ")",
                     "choose a writable directory");
  }
}

OutputDirectory::~OutputDirectory() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
}

bool OutputDirectory::Commit(std::string* error) {
  std::error_code ec;
  const std::string old = final_ + ".old-" + std::to_string(::getpid());
  const bool had_previous = fs::exists(final_, ec);
  if (had_previous) {
    fs::rename(final_, old, ec);
    if (ec) {
      if (error) *error = "cannot move the previous '" + final_ + "' aside: " + ec.message();
      return false;
    }
  }
  fs::rename(temporary_, final_, ec);
  if (ec) {
    if (had_previous) fs::rename(old, final_, ec);
    if (error) *error = "cannot rename '" + temporary_ + "' to '" + final_ + "'";
    return false;
  }
  committed_ = true;
  if (had_previous) fs::remove_all(old, ec);
  return true;
}

}  // namespace ergo
