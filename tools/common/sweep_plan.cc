#include "tools/common/sweep_plan.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"

namespace ergo {
namespace {

[[noreturn]] void VaryError(const std::string& spec, const std::string& what) {
  throw InputError("--vary", "", "'" + spec + "': " + what,
                   "write --vary=NAME=V1,V2,... or --vary=NAME=FROM:TO[:STEP], e.g. "
                   "--vary=gamma_power=-2:1 or --vary=exponent=2,3,4");
}

bool ParseNumber(const std::string& text, double* value) {
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return !text.empty() && end != text.c_str() && *end == '\0' && std::isfinite(*value);
}

bool IsWhole(double value) { return std::abs(value) < 1e15 && value == std::round(value); }

std::string FormatValue(double value, bool whole) {
  char text[64];
  if (whole) {
    std::snprintf(text, sizeof text, "%lld", static_cast<long long>(std::llround(value)));
  } else {
    std::snprintf(text, sizeof text, "%.12g", value);
  }
  return text;
}

std::vector<std::string> RangeValues(const std::string& spec, const std::string& range) {
  const std::vector<std::string> parts = SplitList(range, ':');
  if (parts.size() != 2 && parts.size() != 3) VaryError(spec, "a range is FROM:TO or FROM:TO:STEP");
  double from, to, step = 1;
  if (!ParseNumber(parts[0], &from) || !ParseNumber(parts[1], &to) ||
      (parts.size() == 3 && !ParseNumber(parts[2], &step)))
    VaryError(spec, "the range's ends and step must be finite numbers");
  if (step == 0 || (to - from) * step < 0) {
    VaryError(spec, "the step must be non-zero and point from FROM to TO (e.g. 1:0:-0.25)");
  }
  // Inclusive of TO up to rounding: 0:1:0.1 has eleven values.
  const double count = std::floor((to - from) / step + 1e-9) + 1;
  if (count > 1000) VaryError(spec, "more than 1000 values");
  const bool whole = IsWhole(from) && IsWhole(step);
  std::vector<std::string> values;
  for (long k = 0; k < static_cast<long>(count); ++k)
    values.push_back(FormatValue(from + static_cast<double>(k) * step, whole));  // no drift
  return values;
}

// A directory name: letters, digits and . _ = + - kept, anything else as '_'.
std::string Sanitised(const std::string& text) {
  std::string name = text;
  for (char& c : name) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '=' || c == '+' || c == '-';
    if (!safe) c = '_';
  }
  if (name.empty() || name[0] == '.' || name[0] == '-') name = "_" + name;
  return name.substr(0, 200);
}

}  // namespace

SweepAxis ParseSweepAxis(const std::string& spec) {
  const size_t equals = spec.find('=');
  if (equals == std::string::npos || equals == 0) VaryError(spec, "no NAME= before the values");
  SweepAxis axis;
  axis.flag = spec.substr(0, equals);
  if (axis.flag.rfind("--", 0) == 0) axis.flag = axis.flag.substr(2);
  for (char c : axis.flag) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      VaryError(spec, "'" + axis.flag + "' is not a flag name");
  }
  const std::string values = spec.substr(equals + 1);
  if (values.empty()) VaryError(spec, "no values");
  if (values.find(':') != std::string::npos && values.find(',') == std::string::npos) {
    axis.values = RangeValues(spec, values);
  } else {
    axis.values = SplitList(values, ',');
    for (const std::string& value : axis.values)
      if (value.empty()) VaryError(spec, "an empty value");
    if (axis.values.empty()) VaryError(spec, "no values");
  }
  return axis;
}

std::vector<SweepCase> SweepCases(const std::vector<SweepAxis>& axes) {
  std::vector<SweepCase> cases(1);
  for (const SweepAxis& axis : axes) {
    std::vector<SweepCase> grown;
    for (const SweepCase& partial : cases) {
      for (const std::string& value : axis.values) {
        SweepCase c = partial;
        c.flags.emplace_back(axis.flag, value);
        grown.push_back(std::move(c));
      }
    }
    cases = std::move(grown);
  }
  std::set<std::string> taken;
  for (SweepCase& c : cases) {
    std::string text;
    for (const auto& [flag, value] : c.flags)
      text += (text.empty() ? "" : "__") + flag + "=" + value;
    std::string name = Sanitised(text);
    for (int k = 2; !taken.insert(name).second; ++k)
      name = Sanitised(text) + "_" + std::to_string(k);
    c.name = name;
  }
  return cases;
}

}  // namespace ergo
