// Work in child processes: each piece runs in its own fork with a time limit, its output
// captured, so a crash, an abort, running out of memory or a hang becomes a result. Up to
// `parallel` children run at once; a finished piece's callback may submit more. Pieces of one
// group may share a child, one after another (fewer processes to start), each still with the
// outcome and the console its own child would have given it.
#pragma once

#include <deque>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace bb {

struct ChildOutcome {
  enum class Kind { Done, Crashed, Timeout };
  Kind kind = Kind::Done;
  std::string payload;   ///< what the work returned (Done)
  std::string reason;    ///< the signal, exit code or limit, and what the child printed
  std::string console;   ///< everything the child wrote to stdout and stderr
  double seconds = 0.0;  ///< wall time from the fork to the child's end (0 in this process)
};

/// Memory a child may map beyond what it inherits at fork, before allocations fail (not
/// applied under AddressSanitizer).
inline constexpr long kChildMemoryBytes = 4L << 30;

/// Whether children get that cap: not in a build of this library under AddressSanitizer (its
/// shadow memory takes terabytes of address space), whatever the caller was compiled with.
bool children_memory_capped();

class ChildPool {
 public:
  /// `isolated` false runs every piece in this process, one after another (for debugging).
  ChildPool(int parallel, bool isolated)
      : parallel_(parallel < 1 ? 1 : parallel), isolated_(isolated) {}
  using Work = std::function<std::string()>;
  using Done = std::function<void(const ChildOutcome&)>;
  /// `label` names the piece if it must be stopped; `timeout` is in seconds. A free slot
  /// takes the queued piece of the highest `priority`, the first submitted among equals.
  /// Returns the piece's number, for cancel(). Queued pieces of one non-empty `group` may
  /// run one after another in one child (child_batch.hpp); when a piece in a shared child
  /// crashes, hangs or runs out of memory, the pieces of it not yet done run again, each in
  /// a child of its own, so every outcome is the one its own child gives.
  long submit(std::string label, Work work, double timeout, Done done, double priority = 0.0,
              std::string group = "");
  /// Drops piece `number` if queued, or stops its child if running (killed before the pool
  /// starts another; a child shared with other pieces goes on for them); its callback is
  /// never called. A piece already done is left as it is.
  void cancel(long number);
  /// Children that could start now with nothing queued for them (0 when not isolated: in
  /// this process pieces run one after another).
  int free_slots() const;
  /// Runs until every piece is done; throws Interrupted on a stop signal (interrupt.hpp).
  void run();

 private:
  struct Job {
    std::string label;
    Work work;
    double timeout;
    Done done;
    double priority;
    long number;
    std::string group;
  };
  struct Active;
  void run_in_process();
  void run_isolated();
  /// Forks a child for `jobs` (one, or a group's to run one after another), with pipes for
  /// its results and its console.
  static Active start_child(std::vector<Job> jobs);
  /// Calls back each piece of a shared child whose frame has come (a callback may throw).
  void deliver_frames(Active& a);
  /// Queues again, each for a child of its own, the pieces of a shared child not done.
  void requeue_rest(Active& a);
  /// Reads what each child wrote since the last look, closing a pipe at its end.
  static void read_output(std::vector<Active>& active);
  /// The outcome of a child that closed its output (`closed`) or ran out of time.
  static ChildOutcome finish(Active& a, bool closed);
  /// Takes the queued piece of the highest priority and, when `shared`, the queued pieces of
  /// its group (at most an equal share of the queue per slot, so no slot waits while one
  /// child holds the work).
  std::vector<Job> take_next(bool shared);

  int parallel_;
  bool isolated_;
  std::deque<Job> queue_;
  int running_ = 0;  ///< children started and not yet finished
  long submitted_ = 0;
  std::set<long> cancelled_;  ///< running pieces to stop
};

}  // namespace bb
