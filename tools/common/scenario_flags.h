// The scenario a tool works on, chosen by flags: --scenario=NAME plus that scenario's own
// flags (prefixed with its name, e.g. --bump_height), or all of them from a --flagfile
// (data/SCENARIO.flags). Shared by ergo_compare and ergo_optimize. To add a scenario:
// define its flags in scenario_flags.cc and add one entry to the table there.
#pragma once

#include <string>

#include <gflags/gflags.h>

#include "problems/scenario.h"

DECLARE_string(scenario);

namespace ergo {

// The scenario named by --scenario, built from its flags. Throws InputError naming the
// flag and the fix (unknown name, unusable option).
Scenario ScenarioFromFlags();

// "bump, ..." — the names --scenario accepts, for usage messages.
std::string ScenarioNames();

}  // namespace ergo
