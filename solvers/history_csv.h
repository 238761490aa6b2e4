// CSV output of optimiser runs (written atomically, ergo/mesh/atomic_file.h): one history
// per run — iteration, evaluations, newton_iterations, wall_s, phi, zeta, psi, grad_norm
// (empty where ∇φ was not evaluated), step (largest vertex move from the previous iterate,
// m) — and the comparison table of several runs on one problem.
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
