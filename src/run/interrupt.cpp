#include "run/interrupt.hpp"

#include <csignal>
#include <string>

namespace bb {

namespace {
volatile std::sig_atomic_t arrived = 0;
void on_signal(int signal) {
  arrived = signal;
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() {
  return arrived;
}

void stop_if_interrupted_after(const std::string& written) {
  if (arrived != 0)
    throw Interrupted(written + " was written in full; the program stopped after it");
}

DeferSignals::DeferSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigprocmask(SIG_BLOCK, &set, nullptr);
}

DeferSignals::~DeferSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigprocmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace bb
