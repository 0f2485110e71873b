#include "run/interrupt.hpp"

#include <csignal>
#include <string>

namespace bb {

namespace {
volatile std::sig_atomic_t arrived = 0;
void on_signal(int signal) {
  // The first signal is the one the exit code reports.
  if (arrived == 0) arrived = signal;
}

/// The signals that stop a command cleanly: Ctrl-C, a kill, a closed terminal, and a
/// reader that went away (`beachball run ... | head -1`).
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

void set_handler(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  for (int s : kStopSignals) sigaction(s, &action, nullptr);
}

sigset_t stop_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  for (int s : kStopSignals) sigaddset(&set, s);
  return set;
}
}  // namespace

void install_interrupt_handlers() {
  set_handler(on_signal);
}

void restore_default_signal_handlers() {
  set_handler(SIG_DFL);
}

int interrupt_signal() {
  return arrived;
}

void stop_if_interrupted_after(const std::string& written) {
  if (arrived != 0)
    throw Interrupted(written + " was written in full; the program stopped after it");
}

DeferSignals::DeferSignals() {
  const sigset_t set = stop_signal_set();
  sigprocmask(SIG_BLOCK, &set, nullptr);
}

DeferSignals::~DeferSignals() {
  const sigset_t set = stop_signal_set();
  sigprocmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace bb
