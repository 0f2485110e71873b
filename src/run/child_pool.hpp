// Work in child processes: each piece runs in its own fork with a time limit, its output
// captured, so a crash, an abort, running out of memory or a hang becomes a result. Up to
// `parallel` children run at once; a finished piece's callback may submit more.
#pragma once

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace bb {

struct ChildOutcome {
  enum class Kind { Done, Crashed, Timeout };
  Kind kind = Kind::Done;
  std::string payload;  ///< what the work returned (Done)
  std::string reason;   ///< the signal, exit code or limit, and what the child printed
  std::string console;  ///< everything the child wrote to stdout and stderr
};

/// Memory a child may map beyond what it inherits at fork, before allocations fail (not
/// applied under AddressSanitizer).
inline constexpr long kChildMemoryBytes = 4L << 30;

class ChildPool {
 public:
  /// `isolated` false runs every piece in this process, one after another (for debugging).
  ChildPool(int parallel, bool isolated)
      : parallel_(parallel < 1 ? 1 : parallel), isolated_(isolated) {}
  using Work = std::function<std::string()>;
  using Done = std::function<void(const ChildOutcome&)>;
  /// `label` names the piece if it must be stopped; `timeout` is in seconds.
  void submit(std::string label, Work work, double timeout, Done done);
  /// Runs until every piece is done; throws Interrupted on a stop signal (interrupt.hpp).
  void run();

 private:
  struct Job {
    std::string label;
    Work work;
    double timeout;
    Done done;
  };
  struct Active;
  void run_in_process();
  void run_isolated();
  /// Forks a child for `job`, with pipes for its result and its console.
  static Active start_child(Job job);
  /// Reads what each child wrote since the last look, closing a pipe at its end.
  static void read_output(std::vector<Active>& active);
  /// The outcome of a child that closed its output (`closed`) or ran out of time.
  static ChildOutcome finish(Active& a, bool closed);

  int parallel_;
  bool isolated_;
  std::deque<Job> queue_;
};

}  // namespace bb
