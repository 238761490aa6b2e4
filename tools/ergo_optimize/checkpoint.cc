#include "tools/ergo_optimize/checkpoint.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

#include <gflags/gflags.h>

#include "ergo/design/evaluation_timing.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"

namespace ergo {
namespace {

constexpr int kVersion = 1;

Json Numbers(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v[i]);
  return out;
}

Json Numbers(const std::vector<double>& v) {
  Json out = Json::array();
  for (double x : v) out.push_back(x);
  return out;
}

// A list of numbers written by Numbers (null where the number was not finite).
std::vector<double> ToVector(const Json& array, const std::string& source,
                             const std::string& member) {
  std::vector<double> out;
  const bool numbers =
      array.is_array() && std::all_of(array.begin(), array.end(),
                                      [](const Json& x) { return x.is_number() || x.is_null(); });
  if (!numbers) {
    throw InputError(source, "member \"" + member + "\"", "is not an array of numbers",
                     "start the run afresh");
  }
  for (const Json& x : array)
    out.push_back(x.is_null() ? std::numeric_limits<double>::quiet_NaN() : x.get<double>());
  return out;
}

}  // namespace

std::string CheckpointPath(const std::string& dir) {
  std::error_code ec;
  std::string base = std::filesystem::absolute(dir, ec).lexically_normal().string();
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  return base + ".checkpoint.json";
}

std::string RunFingerprint() {
  static const std::set<std::string> kIgnored = {"out",
                                                 "resume",
                                                 "max_evals",
                                                 "max_seconds",
                                                 "threads",
                                                 "progress",
                                                 "plot",
                                                 "vtu_format",
                                                 "checkpoint_every",
                                                 "flagfile",
                                                 "fromenv",
                                                 "tryfromenv",
                                                 "undefok",
                                                 "help",
                                                 "helpfull",
                                                 "helpshort",
                                                 "helpon",
                                                 "helpmatch",
                                                 "helppackage",
                                                 "helpxml",
                                                 "version",
                                                 "logtostderr",
                                                 "minloglevel",
                                                 "alsologtostderr",
                                                 "log_dir",
                                                 "v",
                                                 "vmodule",
                                                 "stderrthreshold",
                                                 "colorlogtostderr",
                                                 "logbuflevel",
                                                 "logbufsecs",
                                                 "max_log_size",
                                                 "stop_logging_if_full_disk",
                                                 "log_prefix",
                                                 "log_link",
                                                 "drop_log_memory",
                                                 "logemaillevel",
                                                 "logmailer",
                                                 "alsologtoemail",
                                                 "log_backtrace_at",
                                                 "symbolize_stacktrace",
                                                 "timestamp_in_logfile_name",
                                                 "log_year_in_prefix",
                                                 "log_utc_time",
                                                 "log_file_header"};
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);
  std::ostringstream out;
  for (const gflags::CommandLineFlagInfo& flag : flags) {
    if (kIgnored.count(flag.name)) continue;
    out << flag.name << "=" << flag.current_value << "\n";
  }
  return out.str();
}

// The run's budget flags: taken from the checkpoint on resume unless given again.
constexpr const char* kBudgetFlags[] = {"max_evals", "max_seconds"};

void WriteCheckpoint(const std::string& path, const RoundsState& state,
                     const std::string& fingerprint) {
  Json j = Json::object();
  j["version"] = kVersion;
  j["fingerprint"] = fingerprint;
  Json budget = Json::object();
  for (const char* name : kBudgetFlags) {
    std::string value;
    if (gflags::GetCommandLineOption(name, &value)) budget[name] = value;
  }
  j["budget"] = budget;
  j["kept_x"] = Numbers(state.kept_x);
  j["kept_fresh_phi"] = state.kept_fresh_phi;
  j["kept_followed_phi"] = state.kept_followed_phi;
  j["evaluations"] = state.evaluations;
  j["newton_iterations"] = state.newton_iterations;
  j["failed_evaluations"] = state.failed_evaluations;
  j["time_split"] = TimingJson(state.timing);
  j["rounds"] = state.rounds;
  j["next_iteration"] = state.next_iteration;
  j["seconds"] = state.seconds;
  j["candidate_phi"] = Numbers(state.candidate_phi);
  j["candidate_fresh_phi"] = Numbers(state.candidate_fresh_phi);
  j["kept_candidate"] = state.kept_candidate;
  j["finished"] = state.finished;
  j["stop_reason"] = state.stop_reason;
  Json history = Json::array(), history_terms = Json::array(), history_timing = Json::array();
  for (const IterationRecord& r : state.history) {
    history.push_back(Json::array({r.iteration, r.evaluations, r.newton_iterations, r.seconds,
                                   r.phi, r.gradient_norm, r.step, r.kept_fresh_phi}));
    Json terms = Json::array();
    for (const ObjectiveTerm& term : r.terms)
      terms.push_back(Json::array({term.name, term.weight, term.value}));
    history_terms.push_back(terms);
    history_timing.push_back(TimingJson(r.timing));
  }
  j["history"] = history;
  j["history_terms"] = history_terms;
  j["history_time_split"] = history_timing;
  WriteJsonFile(path, j, 0);
}

namespace {

// The checkpoint's JSON; a missing or unreadable file is the user's --resume.
Json ReadCheckpointJson(const std::string& path) {
  try {
    return ReadJsonFile(path);
  } catch (const InputError& error) {
    throw InputError("--resume", "", std::string("cannot read the checkpoint: ") + error.what(),
                     "resume a run that wrote one (ergo_optimize --out=DIR writes "
                     "DIR.checkpoint.json after its rounds)");
  }
}

}  // namespace

void ApplyCheckpointFlags(const std::string& path) {
  const Json j = ReadCheckpointJson(path);
  std::istringstream lines(GetString(j, "fingerprint", path));
  std::string line;
  while (std::getline(lines, line)) {
    const size_t equals = line.find('=');
    if (equals == std::string::npos) continue;
    const std::string name = line.substr(0, equals), value = line.substr(equals + 1);
    gflags::CommandLineFlagInfo info;
    if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
      throw InputError("--resume", "",
                       "the checkpoint names a flag this tool does not have (--" + name + ")",
                       "resume with the ergo_optimize that wrote it");
    }
    if (!info.is_default && info.current_value != value) {
      throw InputError(
          "--" + name, "",
          "is " + info.current_value + " here but " + value + " in the checkpoint " + path,
          "leave it out: --resume takes the checkpoint's flags");
    }
    gflags::SetCommandLineOption(name.c_str(), value.c_str());
  }
  // The budget of the run that wrote it, unless this command line gives another.
  if (const Json* budget = FindMember(j, "budget")) {
    for (const char* name : kBudgetFlags) {
      const Json* value = FindMember(*budget, name);
      gflags::CommandLineFlagInfo info;
      if (value && gflags::GetCommandLineFlagInfo(name, &info) && info.is_default)
        gflags::SetCommandLineOption(name, GetString(*budget, name, path).c_str());
    }
  }
}

RoundsState ReadCheckpoint(const std::string& path, const std::string& fingerprint) {
  const Json j = ReadCheckpointJson(path);
  const std::string source = path;
  if (GetNumber(j, "version", source) != kVersion)
    throw InputError(path, "", "is a checkpoint of another version", "start the run afresh");
  const std::string written = GetString(j, "fingerprint", source);
  if (written != fingerprint) {
    // Name the first flag that differs.
    std::istringstream a(written), b(fingerprint);
    std::string line_a, line_b;
    while (std::getline(a, line_a) && std::getline(b, line_b) && line_a == line_b) {
    }
    throw InputError("--resume", "",
                     "the checkpoint " + path + " was written with other flags (it has '" + line_a +
                         "', this run '" + line_b + "')",
                     "resume with the flags of the run that wrote it");
  }
  RoundsState state;
  const std::vector<double> x = ToVector(GetMember(j, "kept_x", source), source, "kept_x");
  state.kept_x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  state.kept_fresh_phi = GetNumber(j, "kept_fresh_phi", source);
  state.kept_followed_phi = GetNumber(j, "kept_followed_phi", source);
  state.evaluations = static_cast<long>(GetNumber(j, "evaluations", source));
  state.newton_iterations = static_cast<long>(GetNumber(j, "newton_iterations", source));
  state.failed_evaluations = static_cast<long>(GetNumber(j, "failed_evaluations", source));
  // The time split (absent from checkpoints written before it existed: zeros).
  if (const Json* timing = FindMember(j, "time_split"))
    state.timing = TimingFromJson(*timing, source);
  state.rounds = static_cast<int>(GetNumber(j, "rounds", source));
  state.next_iteration = static_cast<int>(GetNumber(j, "next_iteration", source));
  state.seconds = GetNumber(j, "seconds", source);
  state.candidate_phi = ToVector(GetMember(j, "candidate_phi", source), source, "candidate_phi");
  state.candidate_fresh_phi =
      ToVector(GetMember(j, "candidate_fresh_phi", source), source, "candidate_fresh_phi");
  state.kept_candidate = static_cast<int>(GetNumber(j, "kept_candidate", source));
  state.finished = GetBool(j, "finished", source);
  state.stop_reason = GetString(j, "stop_reason", source);
  const Json& history = GetMember(j, "history", source);
  if (!history.is_array())
    throw InputError(path, "member \"history\"", "is not an array", "start the run afresh");
  for (const Json& entry : history) {
    const std::vector<double> h = ToVector(entry, source, "history");
    // Eight entries, the terms in "history_terms"; nine or ten: a checkpoint written before
    // the terms were named (ζ and ψ inline) or before kept_fresh_phi was recorded.
    if (h.size() < 8 || h.size() > 10)
      throw InputError(path, "", "has a malformed history entry", "start afresh");
    IterationRecord r;
    r.iteration = static_cast<int>(h[0]);
    r.evaluations = static_cast<long>(h[1]);
    r.newton_iterations = static_cast<long>(h[2]);
    r.seconds = h[3];
    r.phi = h[4];
    if (h.size() == 8) {
      r.gradient_norm = h[5];
      r.step = h[6];
      r.kept_fresh_phi = h[7];
    } else {
      // φ = ζ + γψ gives the weight γ the old layout did not store.
      const double zeta = h[5], psi = h[6];
      r.terms = {{"zeta", 1, zeta}, {"psi", psi > 0 ? (r.phi - zeta) / psi : 0.0, psi}};
      r.gradient_norm = h[7];
      r.step = h[8];
      if (h.size() == 10) r.kept_fresh_phi = h[9];
    }
    state.history.push_back(r);
  }
  if (const Json* terms = FindMember(j, "history_terms")) {
    if (!terms->is_array() || terms->size() != state.history.size())
      throw InputError(path, "member \"history_terms\"", "does not match the history",
                       "start the run afresh");
    for (size_t i = 0; i < state.history.size(); ++i) {
      for (const Json& term : (*terms)[i]) {
        if (!term.is_array() || term.size() != 3 || !term[0].is_string() || !term[1].is_number() ||
            !term[2].is_number())
          throw InputError(path, "member \"history_terms\"", "has a malformed term",
                           "start the run afresh");
        state.history[i].terms.push_back(
            {term[0].get<std::string>(), term[1].get<double>(), term[2].get<double>()});
      }
    }
  }
  const Json* history_timing = FindMember(j, "history_time_split");
  if (history_timing && history_timing->is_array() &&
      history_timing->size() == state.history.size()) {
    for (size_t i = 0; i < state.history.size(); ++i)
      state.history[i].timing = TimingFromJson((*history_timing)[i], source);
  }
  return state;
}

}  // namespace ergo
