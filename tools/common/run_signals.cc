#include "tools/common/run_signals.h"

#include <csignal>

#include <unistd.h>

namespace ergo {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void OnStopSignal(int signal) {
  if (g_stop.exchange(true)) {
    // The second signal: end now, as the default action would.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    _exit(128 + signal);
  }
  g_signal = signal;
}

}  // namespace

StopOnSignals::StopOnSignals() {
  g_stop = false;
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

StopOnSignals::~StopOnSignals() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

const std::atomic<bool>& StopOnSignals::flag() { return g_stop; }
int StopOnSignals::signal_number() { return g_signal.load(); }
int StopOnSignals::ExitCode() {
  const int signal = g_signal.load();
  return signal == 0 ? 0 : 128 + signal;
}

}  // namespace ergo
