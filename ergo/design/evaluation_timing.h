// EvaluationTiming: where the time of one design evaluation (DesignProblem::Evaluate, φ of
// paper §4 and its adjoint gradient, Eq. 17–20) went, part by part, with the counts that
// explain it (Newton iterations, factorisations, PCG iterations, line-search trials). The
// parts are disjoint intervals inside the evaluation's wall time; what none of them covers
// (copies, the Newton loop's step control, bookkeeping) is other_seconds(), so a reader sees
// what is not accounted for. `+=` sums evaluations (a run, or the placements of a robust
// objective). Seconds are wall time of the thread that evaluated: a sum over evaluations run
// in parallel (probes, robust placements) exceeds the wall clock of the run.
//
//   DesignEvaluation e = problem.Evaluate(x, true);
//   std::cout << e.timing.BriefReport() << "\n";  // "1.2 s: factorisation 0.51 s (2), ..."
#pragma once

#include <functional>
#include <string>

#include "ergo/mesh/json.h"

namespace ergo {

struct EvaluationTiming {
  double total_seconds = 0;  // the evaluations, wall (summed)
  // The parts, seconds.
  double support_seconds = 0;    // the support at x: positions from the design, AABB-tree rebuild
  double placement_seconds = 0;  // the solve's start: placed afresh (PlaceAboveSupport) or the
                                 // nearest warm start looked up
  double predictor_seconds = 0;  // the tangent predictor of a warm start (one PCG solve with the
                                 // last factor, two energies)
  double contact_seconds = 0;    // contact detection and springs at the Newton iterates
  double assembly_seconds = 0;   // elastic assembly and reduction at the Newton iterates
  double factorization_seconds = 0;  // numeric Cholesky factorisations of the Newton matrix
  double solve_seconds = 0;          // Newton steps: PCG on reused factors, triangular solves
  double line_search_seconds = 0;    // the line searches' trials (energy with contact detection)
  double pressure_seconds = 0;       // ζ: both surfaces' pressures from the springs
  double psi_seconds = 0;            // ψ and its gradient pulled back to the design
  // The gradient of ζ: the exact K̂ at y* where Newton's last matrix was not it, the adjoint
  // solve, the shape terms, the pull-back to the design.
  double adjoint_seconds = 0;
  // Counts.
  long equilibria = 0;              // equilibrium solves (K per K-placement robust evaluation)
  long newton_iterations = 0;       // EquilibriumResult::iterations
  long factorizations = 0;          // the equilibrium's numeric factorisations
  long pcg_iterations = 0;          // the equilibrium's PCG iterations on reused factors
  long line_search_trials = 0;      // energy evaluations of the line searches
  long adjoint_factorizations = 0;  // 0 where PCG with the Newton factor solved the adjoint
  long adjoint_pcg_iterations = 0;
  long fresh_placements = 0;  // solves that started from the body placed afresh

  EvaluationTiming& operator+=(const EvaluationTiming& other);
  double PartsSeconds() const;  // the sum of the parts
  double other_seconds() const { return total_seconds - PartsSeconds(); }
  std::string BriefReport() const;  // one line: total, the largest parts, the counts
};

// Every entry as the outputs name it, in output order: "evaluation_s" (the total), the parts
// ("support_s" … "adjoint_s"), "other_s", then the counts ("equilibria" …). These are the
// history.csv columns (solvers/history_csv.h), the keys of summary.json's time_split and the
// benchmark counters. `seconds` gets the seconds, `count` the counts.
void ForEachTimingEntry(const EvaluationTiming& timing,
                        const std::function<void(const char* name, double seconds)>& seconds,
                        const std::function<void(const char* name, long count)>& count);
// Sets the entry `name` (other_s is derived: accepted and ignored); false for a name that is
// not an entry.
bool SetTimingEntry(const std::string& name, double value, EvaluationTiming* timing);

// {"evaluation_s": …, …, "fresh_placements": …} (counts as integers); and back. The reader
// takes the entries it knows and throws InputError naming `source` for a value that is not
// a number.
Json TimingJson(const EvaluationTiming& timing);
EvaluationTiming TimingFromJson(const Json& json, const std::string& source);

}  // namespace ergo
