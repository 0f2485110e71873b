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

/// The signals that stop a command cleanly: Ctrl-C, a kill, a closed terminal, a reader
/// that went away (`beachball run ... | head -1`), and a file grown past `ulimit -f`.
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ};

void set_handler(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  for (int s : kStopSignals) {
    // A file size limit whose signal the caller ignores (`trap '' XFSZ`) makes a write fail
    // as a full disk does, and is left so.
    struct sigaction before {};
    if (s == SIGXFSZ && handler != SIG_DFL && sigaction(s, nullptr, &before) == 0 &&
        before.sa_handler == SIG_IGN)
      continue;
    sigaction(s, &action, nullptr);
  }
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
  // A child's file past the limit fails as a full disk does (its writes say so), rather
  // than killing the run.
  signal(SIGXFSZ, SIG_IGN);
}

std::string interrupt_description() {
  const int s = arrived;
  if (s == SIGXFSZ) return "stopped by signal 25: file size limit reached (ulimit -f)";
  return "interrupted by signal " + std::to_string(s);
}

void stop_if_interrupted(const std::string& during) {
  if (arrived != 0)
    throw Interrupted("stopped during " + during +
                      "; what was under way was rolled back, and earlier outputs are as they were");
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
