// The scenarios of a population file (problems/population.h): each body is the population's
// flagfile, then what the user typed on the command line, then the body's own flags; the
// scene builds it as it would for `ergo_optimize` with those flags. Used by ergo_population.
#pragma once

#include <string>

#include "problems/population.h"
#include "problems/scenario.h"

namespace ergo {

// Reads the population's flagfile into the flags, then parses the command line again so
// that what the user typed wins over the file. Throws InputError naming the flagfile.
void ApplyPopulationFlagfile(const PopulationSpec& spec, int argc, char** argv);

// The scenario with `flags` set over the current ones (restored on return), the design
// flags applied (ApplyDesignFlags). Throws InputError naming the population file and `who`
// ("body small-soft", "the support") for a flag that does not exist or a value it refuses.
Scenario ScenarioWithFlags(const PopulationSpec& spec, const FlagValues& flags,
                           const std::string& who);

}  // namespace ergo
