#include "problems/population.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

// Flags whose values name files: resolved against the population file's folder.
const std::set<std::string>& PathFlags() {
  static const std::set<std::string> flags = {"body_dir",  "skin",          "tet_mesh",
                                              "depth_csv", "stiffness_csv", "support_mesh"};
  return flags;
}

bool IsFlagName(const std::string& name) {
  if (name.empty() || !std::islower(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) ||
           std::isdigit(static_cast<unsigned char>(c)) || c == '_';
  });
}

bool IsBodyName(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.') return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
}

std::string Resolve(const std::string& value, const std::filesystem::path& folder) {
  if (value.empty()) return value;
  const std::filesystem::path path(value);
  return path.is_absolute() ? value
                            : std::filesystem::absolute(folder / path).lexically_normal().string();
}

// An object of flag values; numbers and booleans become their JSON spelling ("0.26").
FlagValues ReadFlags(const Json& object, const std::string& source, const std::string& where,
                     const std::filesystem::path& folder) {
  if (!object.is_object())
    throw InputError(source, where, std::string("is ") + JsonTypeName(object) + ", not an object",
                     "give the flags as {\"shoe_foot_length\": 0.26, ...}");
  FlagValues flags;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string& name = it.key();
    if (!IsFlagName(name))
      throw InputError(source, where + ", flag \"" + name + "\"",
                       "is not a flag's name (lower-case letters, digits and '_', no dashes)",
                       "write e.g. \"shoe_body_mass\"");
    const Json& value = it.value();
    std::string text;
    if (value.is_string()) {
      text = value.get<std::string>();
    } else if (value.is_number() || value.is_boolean()) {
      text = value.dump();
    } else {
      throw InputError(source, where + ", flag \"" + name + "\"",
                       std::string("is ") + JsonTypeName(value) + ", not a string or number",
                       "give a value such as 0.26 or \"filtered\"");
    }
    if (text.find('\n') != std::string::npos || text.find('\0') != std::string::npos)
      throw InputError(source, where + ", flag \"" + name + "\"", "holds a line break",
                       "give the value on one line");
    flags[name] = PathFlags().count(name) ? Resolve(text, folder) : text;
  }
  return flags;
}

Json FlagsJson(const FlagValues& flags) {
  Json object = Json::object();
  for (const auto& [name, value] : flags) object[name] = value;
  return object;
}

std::string Shortest(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

}  // namespace

PopulationSpec ReadPopulationFile(const std::string& path) {
  const Json root = ReadJsonFile(path);
  if (!root.is_object())
    throw InputError(path, "", std::string("is ") + JsonTypeName(root) + ", not an object",
                     "see problems/population.h for the layout");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  PopulationSpec spec;
  spec.source = path;
  if (FindMember(root, "description")) spec.description = GetString(root, "description", path);
  if (FindMember(root, "flagfile"))
    spec.flagfile = Resolve(GetString(root, "flagfile", path), folder);
  if (!spec.flagfile.empty() && !std::filesystem::is_regular_file(spec.flagfile))
    throw InputError(path, "member \"flagfile\"", "'" + spec.flagfile + "' is not a file",
                     "give the scene's flagfile relative to the population file, e.g. "
                     "\"shoe.flags\"");
  if (const Json* flags = FindMember(root, "flags"))
    spec.flags = ReadFlags(*flags, path, "member \"flags\"", folder);
  if (const Json* support = FindMember(root, "support"))
    spec.support = ReadFlags(*support, path, "member \"support\"", folder);
  if (const Json* mean = FindMember(root, "mean_body"))
    spec.mean_body = ReadFlags(*mean, path, "member \"mean_body\"", folder);
  const Json& bodies = GetMember(root, "bodies", path);
  if (!bodies.is_array() || bodies.empty())
    throw InputError(path, "member \"bodies\"", "is not a non-empty array",
                     "list the bodies: [{\"name\": \"a\", \"flags\": {...}}, ...]");
  std::set<std::string> names;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const std::string where = "bodies[" + std::to_string(i) + "]";
    const Json& entry = bodies[i];
    if (!entry.is_object())
      throw InputError(path, where, std::string("is ") + JsonTypeName(entry) + ", not an object",
                       "give {\"name\": ..., \"weight\": ..., \"flags\": {...}}");
    PopulationBody body;
    body.name = GetString(entry, "name", path + ", " + where);
    if (!IsBodyName(body.name))
      throw InputError(path, where + ", member \"name\"", "'" + body.name + "' is not usable",
                       "use up to 64 letters, digits, '-', '_' or '.' (it names output files)");
    if (!names.insert(body.name).second)
      throw InputError(path, where + ", member \"name\"", "'" + body.name + "' appears twice",
                       "give every body its own name");
    if (FindMember(entry, "weight")) {
      body.weight = GetNumber(entry, "weight", path + ", " + where);
      if (!(body.weight > 0) || !std::isfinite(body.weight))
        throw InputError(path, where + ", member \"weight\"", "must be a positive number",
                         "e.g. 1 (weights are relative)");
    }
    if (const Json* flags = FindMember(entry, "flags"))
      body.flags = ReadFlags(*flags, path, where + ", member \"flags\"", folder);
    spec.bodies.push_back(std::move(body));
  }
  return spec;
}

Json PopulationJson(const PopulationSpec& spec) {
  Json root = Json::object();
  if (!spec.description.empty()) root["description"] = spec.description;
  if (!spec.flagfile.empty()) root["flagfile"] = spec.flagfile;
  if (!spec.flags.empty()) root["flags"] = FlagsJson(spec.flags);
  root["support"] = FlagsJson(spec.support);
  if (!spec.mean_body.empty()) root["mean_body"] = FlagsJson(spec.mean_body);
  Json bodies = Json::array();
  for (const PopulationBody& body : spec.bodies)
    bodies.push_back(
        {{"name", body.name}, {"weight", body.weight}, {"flags", FlagsJson(body.flags)}});
  root["bodies"] = std::move(bodies);
  return root;
}

FlagRange ParseFlagRange(const std::string& text, const std::string& source) {
  const size_t equals = text.find('=');
  const size_t colon = text.find(':', equals == std::string::npos ? 0 : equals);
  FlagRange range;
  if (equals != std::string::npos) range.flag = text.substr(0, equals);
  bool ok = equals != std::string::npos && colon != std::string::npos && IsFlagName(range.flag);
  if (ok) {
    const std::string low = text.substr(equals + 1, colon - equals - 1);
    const std::string high = text.substr(colon + 1);
    char* end = nullptr;
    range.low = std::strtod(low.c_str(), &end);
    ok = !low.empty() && *end == '\0' && std::isfinite(range.low);
    range.high = std::strtod(high.c_str(), &end);
    ok = ok && !high.empty() && *end == '\0' && std::isfinite(range.high);
  }
  if (!ok)
    throw InputError(source, "", "'" + text + "' is not FLAG=LOW:HIGH",
                     "e.g. shoe_foot_length=0.23:0.29");
  if (range.low > range.high)
    throw InputError(source, "", "'" + text + "': LOW is above HIGH", "swap them");
  return range;
}

PopulationSpec GeneratePopulation(const PopulationGenerator& generator) {
  if (generator.ranges.empty())
    throw InputError("--vary", "", "no range to vary", "e.g. --vary=shoe_foot_length=0.23:0.29");
  if (generator.count < 1 || generator.count > 10000)
    throw InputError("--count", "", "must be between 1 and 10000", "e.g. --count=8");
  PopulationSpec spec;
  spec.description = generator.description;
  spec.flagfile = generator.flagfile;
  spec.support = generator.fixed;
  spec.mean_body = generator.fixed;
  const std::string stem = generator.flagfile.empty()
                               ? std::string("body")
                               : std::filesystem::path(generator.flagfile).stem().string();
  std::mt19937 random(generator.seed);
  const int n = generator.count;
  std::vector<std::vector<int>> strata;  // strata[j][k]: body k's stratum of range j
  for (const FlagRange& range : generator.ranges) {
    if (!(range.low <= range.high))
      throw InputError("--vary", range.flag, "LOW is above HIGH", "swap them");
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    // Fisher–Yates by hand: std::shuffle's sequence differs between standard libraries.
    for (int k = n - 1; k > 0; --k)
      std::swap(order[k], order[static_cast<int>(random() % static_cast<unsigned>(k + 1))]);
    strata.push_back(order);
    const double mid = 0.5 * (range.low + range.high);
    spec.mean_body[range.flag] = Shortest(mid);
    const auto at = generator.support_at.find(range.flag);
    if (at != generator.support_at.end() && at->second == "high")
      spec.support[range.flag] = Shortest(range.high);
    else if (at != generator.support_at.end() && at->second == "low")
      spec.support[range.flag] = Shortest(range.low);
  }
  for (int k = 0; k < n; ++k) {
    PopulationBody body;
    body.name = stem + "-" + std::to_string(k + 1);
    body.flags = generator.fixed;
    for (size_t j = 0; j < generator.ranges.size(); ++j) {
      const FlagRange& range = generator.ranges[j];
      const double u = (strata[j][k] + 0.5) / n;
      body.flags[range.flag] = Shortest(range.low + u * (range.high - range.low));
    }
    spec.bodies.push_back(std::move(body));
  }
  return spec;
}

}  // namespace ergo
