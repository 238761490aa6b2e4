#include "solvers/history_csv.h"

#include <cmath>
#include <ostream>
#include <string>

#include "ergo/mesh/atomic_file.h"

namespace ergo {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

void WriteHistoryCsv(const std::string& path, const OptimizerResult& result) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    // One column per term of φ (a design problem's zeta and psi), by name.
    const std::vector<std::string> names = result.TermNames();
    out << "iteration,evaluations,newton_iterations,wall_s,phi";
    for (const std::string& name : names) out << ',' << CsvField(name);
    out << ",grad_norm,step,kept_fresh_phi";
    // The time split's columns; its newton_iterations is the column above already.
    ForEachTimingEntry(
        EvaluationTiming(), [&](const char* name, double) { out << ',' << name; },
        [&](const char* name, long) {
          if (std::string(name) != "newton_iterations") out << ',' << name;
        });
    out << '\n';
    for (const IterationRecord& r : result.history) {
      out << r.iteration << ',' << r.evaluations << ',' << r.newton_iterations << ',';
      WriteDouble(out, r.seconds);
      out << ',';
      WriteDouble(out, r.phi);
      for (const std::string& name : names) {
        out << ',';
        const double value = TermValue(r.terms, name);
        if (!std::isnan(value)) WriteDouble(out, value);
      }
      out << ',';
      if (r.gradient_norm >= 0) WriteDouble(out, r.gradient_norm);
      out << ',';
      WriteDouble(out, r.step);
      out << ',';
      if (std::isfinite(r.kept_fresh_phi)) WriteDouble(out, r.kept_fresh_phi);
      ForEachTimingEntry(
          r.timing,
          [&](const char*, double seconds) {
            out << ',';
            WriteDouble(out, seconds);
          },
          [&](const char* name, long count) {
            if (std::string(name) != "newton_iterations") out << ',' << count;
          });
      out << '\n';
    }
  });
}

void WriteComparisonCsv(const std::string& path, const std::vector<OptimizerResult>& results) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "optimizer,initial_phi,final_phi,reduction_percent,followed_phi,"
           "followed_reduction_percent,evaluations,newton_iterations,wall_s,stop_reason\n";
    for (const OptimizerResult& r : results) {
      out << CsvField(r.optimizer) << ',';
      if (r.ok) {
        WriteDouble(out, r.initial_phi);
        out << ',';
        WriteDouble(out, r.best_phi);
        out << ',';
        WriteDouble(out, r.ReductionPercent());
        out << ',';
        if (std::isfinite(r.followed_phi)) {
          WriteDouble(out, r.followed_phi);
          out << ',';
          WriteDouble(out, 100 * (1 - r.followed_phi / r.initial_phi));
        } else {
          out << ',';
        }
      } else {
        out << ",,,,";
      }
      out << ',' << r.evaluations << ',' << r.newton_iterations << ',';
      WriteDouble(out, r.seconds);
      out << ',' << CsvField(r.stop_reason) << '\n';
    }
  });
}

}  // namespace ergo
