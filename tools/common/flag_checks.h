// Checks of a tool's command line before gflags parses it, so that every user error exits
// with status 2 and a message naming the flag (gflags itself exits 1 on an unknown flag and
// ignores a --flagfile that is a directory): unknown flags, flagfiles that are missing, not
// regular files or unreadable (also nested ones), and stray positional arguments. Plus the
// range checks the tools' validation functions share. All throw InputError.
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Core>

namespace ergo {

// Throws InputError for the first problem in argv (and the flagfiles it names).
// `positional` = how many positional arguments the tool takes (ergo_mesh: a verb and files).
void CheckCommandLine(int argc, char** argv, int positional = 0);

// When `condition` fails: InputError naming --flag, with `what` is wrong and the `fix`.
void RequireFlag(bool condition, const std::string& flag, const std::string& what,
                 const std::string& fix);

// value must be finite and lie in [low, high]; else InputError naming --flag with `fix`.
void RequireInRange(const char* flag, double value, double low, double high,
                    const std::string& fix);
// The same for integers.
void RequireInRange(const char* flag, long value, long low, long high, const std::string& fix);

// "X,Y,Z" given to --flag: exactly three finite numbers, else InputError naming --flag with
// what it got and `example` (a value to write, e.g. "0,-300,0").
Eigen::Vector3d ParseThreeNumbers(const std::string& flag, const std::string& text,
                                  const std::string& example);

// Sends glog's output to stderr only (no log files in /tmp), before InitGoogleLogging.
void LogToStderrOnly();

}  // namespace ergo
