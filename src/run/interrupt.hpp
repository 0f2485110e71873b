// Ctrl-C, SIGTERM, SIGHUP, SIGPIPE and SIGXFSZ stop a long command cleanly: work stops
// between steps of the pool and between the files of an output, children are killed, and
// nothing half-written is left behind.
#pragma once

#include <stdexcept>
#include <string>

namespace bb {

/// Thrown when an interrupt stops the work; what() says what was running and what the
/// outputs are now.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws Interrupted when a signal arrived while `written` was being written (signals wait
/// during writes): the write was finished, and the program stops there.
void stop_if_interrupted_after(const std::string& written);

/// Throws Interrupted when a signal arrived during `during` (a case's runs taken from kept
/// results, its files, a report's pages): the caller's unwinding rolls back what was under
/// way.
void stop_if_interrupted(const std::string& during);

/// Routes SIGINT, SIGTERM, SIGHUP, SIGPIPE and SIGXFSZ to a flag instead of ending the
/// process: the command finishes or rolls back what it is writing, says so, and exits 128 +
/// the signal.
void install_interrupt_handlers();
/// Gives those signals their default action again (in a child process), but a write past
/// the file size limit fails instead of killing the child.
void restore_default_signal_handlers();
/// The signal that arrived, or 0.
int interrupt_signal();
/// What stopped the program, for its last message: "interrupted by signal 15", or for
/// SIGXFSZ that the file size limit was reached.
std::string interrupt_description();

/// While alive, those signals wait: used around writing outputs, so a report is
/// either the old one or the whole new one.
class DeferSignals {
 public:
  DeferSignals();
  ~DeferSignals();
  DeferSignals(const DeferSignals&) = delete;
  DeferSignals& operator=(const DeferSignals&) = delete;
};

}  // namespace bb
