// Population: the bodies one support is designed for (a manufacturer's one insole size for
// many feet, or one person's foot as it swells and stiffens). A population file (JSON) names
// a scene flagfile shared by every body, the flags that build the shared support, and each
// body as the flags that make it differ — a generated scene's variations (foot length, tissue
// modulus, mass, lean torque), a body directory (--body_dir) or a scan with its priors
// (--skin, --depth_csv, ...) — with a weight:
//
//   {"description": "...", "flagfile": "shoe.flags",
//    "flags": {"robust_placements": 3},
//    "support": {"shoe_foot_length": "0.29"},
//    "mean_body": {"shoe_foot_length": "0.26"},
//    "bodies": [{"name": "small-soft", "weight": 1, "flags": {"shoe_foot_length": "0.24"}},
//               ...]}
//
// "flags" apply to the whole run (the bodies, the support, the run's own flags such as
// robust_placements) after the flagfile and before what the user types. Paths (the flagfile, and
// flag values naming files: body_dir, skin, tet_mesh, depth_csv, stiffness_csv, support_mesh) are
// relative to the population file. Flag values are strings or numbers. GeneratePopulation makes
// such a population from a scene and ranges of its flags (a Latin hypercube: every range sampled
// evenly, the combinations shuffled by a seed).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ergo/mesh/json.h"

namespace ergo {

using FlagValues = std::map<std::string, std::string>;  // flag name (no dashes) → value

struct PopulationBody {
  std::string name;
  double weight = 1;  // > 0, relative
  FlagValues flags;
};

struct PopulationSpec {
  std::string source;       // the file it was read from ("" when generated)
  std::string description;  // one line for reports
  std::string flagfile;     // the scene's flagfile, absolute or relative to the cwd; may be ""
  FlagValues flags;         // the whole run's, over the flagfile's
  FlagValues support;       // flags of the scene whose support every body shares
  FlagValues mean_body;     // the population's mean body (for the comparison); may be empty
  std::vector<PopulationBody> bodies;
};

// Reads and checks a population file: InputError naming the file, the member and the fix
// for malformed JSON, a missing or mistyped member, no bodies, a duplicate or unusable name
// (names become file names: letters, digits, '-', '_', '.'), a weight that is not a positive
// finite number, or a flag name that is not a flag's spelling. Relative paths are resolved
// against the file's folder.
PopulationSpec ReadPopulationFile(const std::string& path);
Json PopulationJson(const PopulationSpec& spec);  // what ReadPopulationFile reads back

// A flag varied over [low, high] across the generated bodies.
struct FlagRange {
  std::string flag;
  double low = 0, high = 0;
};

struct PopulationGenerator {
  std::string description;
  std::string flagfile;           // the scene's flagfile
  std::vector<FlagRange> ranges;  // at least one
  int count = 8;                  // bodies, ≥ 1
  unsigned seed = 1;              // the shuffle of the Latin hypercube
  FlagValues fixed;               // flags every body gets
  // The support is built with each range's `support_at` end (e.g. the longest foot, so that
  // every foot fits on the shared sole): "high", "low" or "" (the scene's default) per flag.
  std::map<std::string, std::string> support_at;
};

// `count` bodies, named NAME-1 … NAME-count after the scene flagfile's stem ("shoe-1"),
// weight 1; body k's value of range j is low + (σ_j(k) + 0.5)/count · (high − low) with σ_j
// a seeded permutation, so every range is covered evenly; the mean body takes every range's
// midpoint. Throws InputError for an empty range list, count < 1 or low > high.
PopulationSpec GeneratePopulation(const PopulationGenerator& generator);

// Parses "FLAG=LOW:HIGH" (a --vary value of `ergo_population --generate`). InputError
// naming `source` otherwise.
FlagRange ParseFlagRange(const std::string& text, const std::string& source);

}  // namespace ergo
