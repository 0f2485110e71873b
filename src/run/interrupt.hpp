// Ctrl-C and SIGTERM stop a long command cleanly: work stops between steps of the pool,
// children are killed, and nothing half-written is left behind.
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

/// Routes SIGINT and SIGTERM to a flag instead of ending the process.
void install_interrupt_handlers();
/// The signal that arrived, or 0.
int interrupt_signal();

/// While alive, SIGINT and SIGTERM wait: used around writing outputs, so a report is
/// either the old one or the whole new one.
class DeferSignals {
 public:
  DeferSignals();
  ~DeferSignals();
  DeferSignals(const DeferSignals&) = delete;
  DeferSignals& operator=(const DeferSignals&) = delete;
};

}  // namespace bb
