#include "tools/common/population_scenarios.h"

#include <vector>

#include <gflags/gflags.h>

#include "ergo/mesh/input_error.h"
#include "tools/common/design_flags.h"
#include "tools/common/scenario_flags.h"

namespace ergo {

namespace {

void SetFlags(const PopulationSpec& spec, const FlagValues& flags, const std::string& who) {
  for (const auto& [name, value] : flags) {
    gflags::CommandLineFlagInfo info;
    if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info))
      throw InputError(spec.source, who + ", flag \"" + name + "\"", "is not a flag",
                       "see ergo_population --help for the scene, design and run flags");
    if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty())
      throw InputError(spec.source, who + ", flag \"" + name + "\"",
                       "'" + value + "' is not a " + info.type, "give a value of that type");
  }
}

}  // namespace

void ApplyPopulationFlagfile(const PopulationSpec& spec, int argc, char** argv) {
  if (!spec.flagfile.empty() &&
      !gflags::ReadFromFlagsFile(spec.flagfile, argv[0], /*errors_are_fatal=*/false))
    throw InputError(spec.flagfile, "", "holds a flag that does not exist or a bad value",
                     "check the population's \"flagfile\" (" + spec.source + ")");
  SetFlags(spec, spec.flags, "member \"flags\"");
  std::vector<char*> again(argv, argv + argc);
  int count = argc;
  char** arguments = again.data();
  gflags::ParseCommandLineNonHelpFlags(&count, &arguments, /*remove_flags=*/false);
}

Scenario ScenarioWithFlags(const PopulationSpec& spec, const FlagValues& flags,
                           const std::string& who) {
  gflags::FlagSaver saver;  // every flag back as it was on return
  SetFlags(spec, flags, who);
  try {
    Scenario scenario = ScenarioFromFlags();
    ApplyDesignFlags(&scenario);
    return scenario;
  } catch (const InputError& error) {
    throw InputError(spec.source, who, error.what(), "change that body's flags");
  }
}

}  // namespace ergo
