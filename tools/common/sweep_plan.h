// The cases of a parameter sweep (`ergo_sweep --vary=NAME=V1,V2,... --vary=NAME=A:B[:STEP]`):
// each --vary is an axis (a flag of ergo_optimize and its values), and the sweep runs the
// cartesian product of the axes, the first axis varying slowest. Every case has a stable
// directory name built from its values, so a sweep run again over the same folder finds the
// cases it already finished.
//
//   const SweepAxis gamma = ParseSweepAxis("gamma_power=-2:1");   // -2, -1, 0, 1
//   const SweepAxis exponent = ParseSweepAxis("exponent=2,3,4");
//   for (const SweepCase& c : SweepCases({gamma, exponent})) ...   // 12 cases
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ergo {

struct SweepAxis {
  std::string flag;                 // e.g. "gamma_power" (without --)
  std::vector<std::string> values;  // as they are passed: "-2", "0.5", "nlopt-mma"
};

// Parses one --vary value: NAME=V1,V2,... (any words; empty ones refused) or NAME=A:B[:STEP]
// (numbers; A to B inclusive in steps of STEP, default 1; integers stay integers). Throws
// InputError naming --vary for a missing name or value, a step of the wrong sign, or a
// range of more than 1000 values.
SweepAxis ParseSweepAxis(const std::string& spec);

struct SweepCase {
  std::vector<std::pair<std::string, std::string>> flags;  // (flag, value) per axis, in order
  std::string name;  // "gamma_power=-2__exponent=3": a directory name (unsafe bytes as '_')
};

// The cartesian product, first axis slowest. Names are unique (a numbered suffix separates
// two that sanitise to the same text).
std::vector<SweepCase> SweepCases(const std::vector<SweepAxis>& axes);

}  // namespace ergo
