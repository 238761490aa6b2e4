// Ctrl-C during a long call of the bindings. Python's own SIGINT handler only marks the
// signal for the interpreter, which cannot look while C++ runs with the GIL released; so
// for the call's duration SIGINT (and SIGTERM) set the library's stop flag instead, the
// computation ends cleanly at its next check (a Newton iteration, an evaluation), and the
// binding raises KeyboardInterrupt afterwards. The previous handlers are restored.
#pragma once

#include <atomic>

namespace ergo::python {

class ScopedInterrupt {
 public:
  ScopedInterrupt();   // installs the handlers (one object at a time; nesting keeps the first)
  ~ScopedInterrupt();  // restores the previous handlers
  ScopedInterrupt(const ScopedInterrupt&) = delete;
  ScopedInterrupt& operator=(const ScopedInterrupt&) = delete;

  // The stop flag to hand to the library (EquilibriumOptions::stop, RunControl::stop).
  const std::atomic<bool>* flag() const;
  bool interrupted() const;

  // Raises KeyboardInterrupt (throws pybind11::error_already_set) if a signal arrived.
  // Call with the GIL held.
  void RaiseIfInterrupted() const;

 private:
  bool installed_ = false;
};

}  // namespace ergo::python
