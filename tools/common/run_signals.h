// Interrupts of a long run: SIGINT (Ctrl-C) and SIGTERM set a stop flag that the run polls,
// so it can finish the work in hand and write complete outputs for the best result so far;
// a second signal ends the process at once (exit 128 + signal). The exit status after a
// clean stop is 130 (SIGINT) or 143 (SIGTERM), as shells report them.
#pragma once

#include <atomic>

namespace ergo {

class StopOnSignals {
 public:
  // Installs the handlers (process-wide; one object at a time).
  StopOnSignals();
  // Restores the default handlers.
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  // Set once a signal arrived; pass to RunControl::stop.
  static const std::atomic<bool>& flag();
  static bool stopped() { return flag().load(); }
  // The signal that arrived (0 if none) and the exit status that reports it (0 if none).
  static int signal_number();
  static int ExitCode();
};

}  // namespace ergo
