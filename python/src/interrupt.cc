#include "python/src/interrupt.h"

#include <csignal>

#include <pybind11/pybind11.h>

namespace ergo::python {
namespace {

std::atomic<bool> stop_flag{false};
std::atomic<int> depth{0};
struct sigaction previous_int, previous_term;

void OnSignal(int) { stop_flag.store(true); }

}  // namespace

ScopedInterrupt::ScopedInterrupt() {
  if (depth.fetch_add(1) != 0) return;  // an outer call owns the handlers
  stop_flag.store(false);
  struct sigaction action = {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
  installed_ = true;
}

ScopedInterrupt::~ScopedInterrupt() {
  depth.fetch_sub(1);
  if (!installed_) return;
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

const std::atomic<bool>* ScopedInterrupt::flag() const { return &stop_flag; }

bool ScopedInterrupt::interrupted() const { return stop_flag.load(); }

void ScopedInterrupt::RaiseIfInterrupted() const {
  if (!interrupted()) return;
  PyErr_SetString(PyExc_KeyboardInterrupt, "interrupted (Ctrl-C): stopped cleanly");
  throw pybind11::error_already_set();
}

}  // namespace ergo::python
