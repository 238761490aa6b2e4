// CSV output of optimiser runs (written atomically, ergo/mesh/atomic_file.h): one history
// per run — iteration, evaluations, newton_iterations, wall_s, phi, one column per
// term of φ by name (a design problem's zeta, psi; an analytic function's f), grad_norm
// (empty where ∇φ was not evaluated), step (largest vertex move from the previous iterate,
// m), kept_fresh_phi (runs in fresh rounds: the score afresh of the design kept at that row;
// empty for other runs), then the time split of the evaluations (ergo/design/evaluation_timing.h) —
// and the comparison table of several runs on one problem.
//
// The time-split columns are cumulative since the start of the run, like `evaluations` and
// `wall_s`, and cover the same evaluations as `evaluations` (probes, failures and fresh
// checks included); zeros for objectives that are not design problems:
//   evaluation_s   the evaluations' own wall times, summed. Evaluations that ran side by side
//                  (paper-ncg's probes, a robust objective's placements, which are summed
//                  per evaluation) each count in full, so it and the parts can exceed wall_s.
//   support_s      support at x: positions from the design and the AABB-tree rebuild
//   placement_s    the solve's start: the body placed afresh (PlaceAboveSupport) or the
//                  nearest warm start looked up
//   predictor_s    the tangent predictor of warm starts
//   contact_s      contact detection and springs at the Newton iterates
//   assembly_s     elastic assembly and reduction at the Newton iterates
//   factorization_s  numeric Cholesky factorisations of the Newton matrix
//   solve_s        Newton steps: PCG on reused factors and triangular solves
//   line_search_s  the line searches' trials (energy with contact detection at each)
//   pressure_s     ζ: both surfaces' pressures from the springs
//   psi_s          ψ and its gradient
//   adjoint_s      the gradient of ζ (adjoint solve, shape terms, pull-back)
//   other_s        evaluation_s minus the parts above: what none of them covers
//   equilibria     equilibrium solves (K per evaluation of a K-placement robust objective)
//   factorizations, pcg_iterations, line_search_trials  the equilibria's
//   adjoint_factorizations, adjoint_pcg_iterations      the gradients'
//   fresh_placements  solves that started from the body placed afresh
// (Newton iterations are the `newton_iterations` column; unlike the split it leaves out the
// fresh checks of runs in rounds.)
#pragma once

#include <string>
#include <vector>

#include "solvers/optimizer.h"

namespace ergo {

// The history of `result`, one row per iteration. Throws InputError if `path` cannot be
// written.
void WriteHistoryCsv(const std::string& path, const OptimizerResult& result);

// One row per run: optimizer, initial_phi, final_phi, reduction_percent (of the kept design
// placed afresh, for runs in fresh rounds), followed_phi, followed_reduction_percent (the
// optimiser's own value there; empty for other runs), evaluations, newton_iterations, wall_s,
// stop_reason.
void WriteComparisonCsv(const std::string& path, const std::vector<OptimizerResult>& results);

// A CSV field, quoted (RFC 4180) when it contains a comma, a quote or a line break.
std::string CsvField(const std::string& text);

}  // namespace ergo
