#include "ergo/design/evaluation_timing.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

// The parts and the counts with their output names, in output order (one list for +=, the
// sum of the parts, the CSV columns, the JSON keys and the reader).
struct SecondsEntry {
  const char* name;
  const char* label;  // for BriefReport
  double EvaluationTiming::*member;
};
struct CountEntry {
  const char* name;
  long EvaluationTiming::*member;
};

constexpr SecondsEntry kParts[] = {
    {"support_s", "support", &EvaluationTiming::support_seconds},
    {"placement_s", "placement", &EvaluationTiming::placement_seconds},
    {"predictor_s", "predictor", &EvaluationTiming::predictor_seconds},
    {"contact_s", "contact", &EvaluationTiming::contact_seconds},
    {"assembly_s", "assembly", &EvaluationTiming::assembly_seconds},
    {"factorization_s", "factorisation", &EvaluationTiming::factorization_seconds},
    {"solve_s", "solves", &EvaluationTiming::solve_seconds},
    {"line_search_s", "line search", &EvaluationTiming::line_search_seconds},
    {"pressure_s", "pressures", &EvaluationTiming::pressure_seconds},
    {"psi_s", "ψ", &EvaluationTiming::psi_seconds},
    {"adjoint_s", "adjoint", &EvaluationTiming::adjoint_seconds},
};

constexpr CountEntry kCounts[] = {
    {"equilibria", &EvaluationTiming::equilibria},
    {"newton_iterations", &EvaluationTiming::newton_iterations},
    {"factorizations", &EvaluationTiming::factorizations},
    {"pcg_iterations", &EvaluationTiming::pcg_iterations},
    {"line_search_trials", &EvaluationTiming::line_search_trials},
    {"adjoint_factorizations", &EvaluationTiming::adjoint_factorizations},
    {"adjoint_pcg_iterations", &EvaluationTiming::adjoint_pcg_iterations},
    {"fresh_placements", &EvaluationTiming::fresh_placements},
};

constexpr const char* kTotal = "evaluation_s";
constexpr const char* kOther = "other_s";

}  // namespace

EvaluationTiming& EvaluationTiming::operator+=(const EvaluationTiming& other) {
  total_seconds += other.total_seconds;
  for (const SecondsEntry& part : kParts) this->*part.member += other.*part.member;
  for (const CountEntry& count : kCounts) this->*count.member += other.*count.member;
  return *this;
}

double EvaluationTiming::PartsSeconds() const {
  double sum = 0;
  for (const SecondsEntry& part : kParts) sum += this->*part.member;
  return sum;
}

std::string EvaluationTiming::BriefReport() const {
  // The parts, largest first, down to a twentieth of the total.
  std::vector<std::pair<double, const char*>> parts;
  for (const SecondsEntry& part : kParts) parts.emplace_back(this->*part.member, part.label);
  parts.emplace_back(other_seconds(), "other");
  std::sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a > b; });
  std::ostringstream out;
  out.precision(3);
  out << total_seconds << " s:";
  const char* separator = " ";
  for (const auto& [seconds, label] : parts) {
    if (!(seconds >= 0.05 * total_seconds) || seconds <= 0) break;
    out << separator << label << " " << seconds << " s";
    separator = ", ";
  }
  out << "; " << newton_iterations << " Newton iterations, " << factorizations << " + "
      << adjoint_factorizations << " (adjoint) factorisations, " << pcg_iterations << " + "
      << adjoint_pcg_iterations << " PCG iterations, " << line_search_trials
      << " line-search trials";
  return out.str();
}

void ForEachTimingEntry(const EvaluationTiming& timing,
                        const std::function<void(const char* name, double seconds)>& seconds,
                        const std::function<void(const char* name, long count)>& count) {
  seconds(kTotal, timing.total_seconds);
  for (const SecondsEntry& part : kParts) seconds(part.name, timing.*part.member);
  seconds(kOther, timing.other_seconds());
  for (const CountEntry& entry : kCounts) count(entry.name, timing.*entry.member);
}

bool SetTimingEntry(const std::string& name, double value, EvaluationTiming* timing) {
  if (name == kTotal) {
    timing->total_seconds = value;
    return true;
  }
  if (name == kOther) return true;
  for (const SecondsEntry& part : kParts) {
    if (name == part.name) {
      timing->*part.member = value;
      return true;
    }
  }
  for (const CountEntry& entry : kCounts) {
    if (name == entry.name) {
      timing->*entry.member = std::lround(value);
      return true;
    }
  }
  return false;
}

Json TimingJson(const EvaluationTiming& timing) {
  Json out = Json::object();
  ForEachTimingEntry(
      timing, [&](const char* name, double seconds) { out[name] = seconds; },
      [&](const char* name, long count) { out[name] = count; });
  return out;
}

EvaluationTiming TimingFromJson(const Json& json, const std::string& source) {
  if (!json.is_object())
    throw InputError(source, "", "the time split is not an object", "start the run afresh");
  EvaluationTiming timing;
  for (const auto& [name, value] : json.items()) {
    if (!value.is_number())
      throw InputError(source, "member \"" + name + "\"", "is not a number",
                       "start the run afresh");
    SetTimingEntry(name, value.get<double>(), &timing);
  }
  return timing;
}

}  // namespace ergo
