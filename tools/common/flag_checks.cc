#include "tools/common/flag_checks.h"

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <sys/stat.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"

namespace ergo {
namespace {

// The flag name of "--name=value", "-name", "--noname" (a negated bool), or "" if none.
bool KnownFlag(const std::string& name) {
  gflags::CommandLineFlagInfo info;
  if (gflags::GetCommandLineFlagInfo(name.c_str(), &info)) return true;
  if (name.rfind("no", 0) == 0 && gflags::GetCommandLineFlagInfo(name.substr(2).c_str(), &info))
    return info.type == "bool";
  return false;
}

std::string FlagName(const std::string& argument) {
  std::string body = argument.substr(argument.rfind("--", 0) == 0 ? 2 : 1);
  return body.substr(0, body.find('='));
}

void CheckFlagfile(const std::string& path, std::set<std::string>* seen, int depth);

// One flag argument ("--name=value"), from the command line or a flagfile (`where`).
void CheckFlag(const std::string& argument, const std::string& where, std::set<std::string>* seen,
               int depth) {
  const std::string name = FlagName(argument);
  if (name.empty())
    throw InputError(where, "", "'" + argument + "' is not a flag", "write --name=value");
  if (!KnownFlag(name)) {
    throw InputError("--" + name, "",
                     "is not a flag of this tool" + (where.empty() ? "" : " (in " + where + ")"),
                     "see --help for its flags");
  }
  if (name == "flagfile") {
    const size_t equals = argument.find('=');
    if (equals == std::string::npos)
      throw InputError("--flagfile", "", "needs a file", "write --flagfile=data/shoe.flags");
    // gflags reads the list the same way (a trailing comma ends the last file name).
    for (const std::string& file : SplitList(argument.substr(equals + 1), ','))
      CheckFlagfile(file, seen, depth + 1);
  }
}

void CheckFlagfile(const std::string& path, std::set<std::string>* seen, int depth) {
  if (depth > 8) throw InputError(path, "", "flagfiles nest deeper than 8", "remove the cycle");
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw InputError("--flagfile", "", "'" + path + "' does not exist",
                     "give the scenario file, e.g. data/shoe.flags");
  if (!S_ISREG(info.st_mode))
    throw InputError("--flagfile", "", "'" + path + "' is not a regular file",
                     "give a flagfile such as data/shoe.flags, not a directory or device");
  std::ifstream in(path);
  if (!in)
    throw InputError("--flagfile", "", "'" + path + "' cannot be read", "check its permissions");
  if (!seen->insert(path).second) return;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const size_t last = line.find_last_not_of(" \t\r");
    const std::string argument = line.substr(first, last - first + 1);
    const std::string where = path + ":" + std::to_string(number);
    if (argument[0] != '-') {
      throw InputError(where, "", "'" + argument + "' is not a flag (gflags would ignore it)",
                       "write one --name=value per line");
    }
    CheckFlag(argument, where, seen, depth);
  }
}

}  // namespace

void CheckCommandLine(int argc, char** argv, int positional) {
  std::set<std::string> seen;
  int positionals = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--") {
      positionals += argc - i - 1;
      break;
    }
    if (argument.size() > 1 && argument[0] == '-') {
      CheckFlag(argument, "", &seen, 0);
      // gflags takes "--name value" for a non-bool flag: the value is the next argument.
      gflags::CommandLineFlagInfo info;
      if (argument.find('=') == std::string::npos &&
          gflags::GetCommandLineFlagInfo(FlagName(argument).c_str(), &info) &&
          info.type != "bool" && i + 1 < argc) {
        if (FlagName(argument) == "flagfile") CheckFlagfile(argv[i + 1], &seen, 1);
        ++i;
      }
      continue;
    }
    if (++positionals > positional) {
      throw InputError("command line", "", "unexpected argument '" + argument + "'",
                       "flags are written --name=value (see --help)");
    }
  }
}

void RequireFlag(bool condition, const std::string& flag, const std::string& what,
                 const std::string& fix) {
  if (!condition) throw InputError("--" + flag, "", what, fix);
}

void RequireInRange(const char* flag, double value, double low, double high,
                    const std::string& fix) {
  if (!std::isfinite(value) || value < low || value > high) {
    std::ostringstream what;
    what << "is " << value << "; it must be a finite number in [" << low << ", " << high << "]";
    throw InputError(std::string("--") + flag, "", what.str(), fix);
  }
}

Eigen::Vector3d ParseThreeNumbers(const std::string& flag, const std::string& text,
                                  const std::string& example) {
  const std::vector<std::string> items = SplitList(text, ',');
  Eigen::Vector3d v;
  bool ok = items.size() == 3;
  for (size_t k = 0; ok && k < 3; ++k) {
    char* end = nullptr;
    v[k] = std::strtod(items[k].c_str(), &end);
    ok = end != items[k].c_str() && *end == '\0' && std::isfinite(v[k]);
  }
  if (!ok) {
    throw InputError("--" + flag, "", "'" + text + "' is not three finite numbers",
                     "write X,Y,Z, e.g. --" + flag + "=" + example);
  }
  return v;
}

void RequireInRange(const char* flag, long value, long low, long high, const std::string& fix) {
  if (value < low || value > high) {
    throw InputError(std::string("--") + flag, "",
                     "is " + std::to_string(value) + "; it must lie in [" + std::to_string(low) +
                         ", " + std::to_string(high) + "]",
                     fix);
  }
}

void LogToStderrOnly() {
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = 1;  // warnings and above
}

}  // namespace ergo
