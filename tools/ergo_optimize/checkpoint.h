// Checkpoints of an ergo_optimize run: the state between two rounds (solvers/fresh_rounds.h:
// the kept design, its scores, the counts and the history so far), written atomically next
// to the output directory as DIR.checkpoint.json, with a fingerprint of every flag that
// poses the problem. `--resume=DIR` reads it back and continues where the killed run was;
// since a round depends only on the design it starts from and the budget left, the resumed
// run ends with the same design and score as an uninterrupted one (bit for bit, with
// evaluation budgets).
#pragma once

#include <string>

#include "solvers/fresh_rounds.h"

namespace ergo {

// The checkpoint file of output directory `dir`.
std::string CheckpointPath(const std::string& dir);

// name=value of every flag except those that do not change the run's result (output
// directory, budget, threads, progress, plotting, the checkpoint flags themselves).
std::string RunFingerprint();

void WriteCheckpoint(const std::string& path, const RoundsState& state,
                     const std::string& fingerprint);

// Reads a checkpoint; throws InputError (naming --resume) when it is missing, unreadable, or
// was written with other flags (listing the first difference).
RoundsState ReadCheckpoint(const std::string& path, const std::string& fingerprint);

// Sets every flag of the run that wrote the checkpoint (so `--resume=DIR` alone poses the same
// problem and budget); a problem flag given on this command line with another value is
// refused (InputError), a budget flag (--max_evals, --max_seconds) given again wins.
void ApplyCheckpointFlags(const std::string& path);

}  // namespace ergo
