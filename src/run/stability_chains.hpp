// The stability searches of a case's backends, run together in child processes. Each search
// is a chain of trials, one asked for at a time; a core that would otherwise wait tries a
// step the slowest waiting search may ask for next (StabilitySearch::likely_next), so one
// backend's long chain does not hold the others' cores idle. A search records only the
// trials it asks for, so its result is that of the search run one trial at a time.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "run/child_pool.hpp"
#include "run/run_cache.hpp"
#include "run/stability.hpp"

namespace bb {

class StabilityChains {
 public:
  struct Options {
    int jobs = 1;
    bool isolation = true;
    double timeout = 0.0;  ///< seconds per trial; 0: from the trial's steps
    const KnownTrials* known = nullptr;
    RunCache* cache = nullptr;
    std::function<void(const std::string&)> on_done;
  };
  StabilityChains(const Scene& scene, std::vector<const Backend*> backends, Options options);
  /// Every search to its end; results in the order of the backends given.
  std::vector<StabilityResult> run();

 private:
  struct Chain {
    Chain(const Backend* b, std::optional<double> limit, StabilitySearch s)
        : backend(b), theory(limit), search(std::move(s)) {}
    const Backend* backend;
    std::optional<double> theory;  ///< the theory's limit for a course variant, if any
    StabilitySearch search;
    std::map<double, StabilityTrial> finished;  ///< run here, not yet asked for
    std::map<double, StabilityTrial> kept;      ///< peeked at in the cache while looking ahead
    std::map<double, long> running;             ///< steps running, with their pieces in the pool
    std::set<double> ahead;      ///< steps run ahead, before the search asked for them
    double child_seconds = 0.0;  ///< wall time of its finished children
    int children = 0;
    bool over = false;
  };
  /// Records every trial the chain's search asks for that is at hand, then runs the next one
  /// (or ends the search).
  void advance(std::size_t i);
  /// A trial at hand for `dt`: run here, judged by an accuracy run, or kept in the cache.
  std::optional<StabilityTrial> at_hand(Chain& c, double dt);
  /// The trial an accuracy run judged on its own steps at `dt`, if it may stand for one.
  const StabilityTrial* judged_by_accuracy(const Chain& c, double dt) const;
  void submit(std::size_t i, double dt, const std::string& key);
  void finished(std::size_t i, double dt, const std::string& key, const ChildOutcome& o);
  /// Fills free cores with the steps the slowest waiting searches may ask for next.
  void look_ahead();
  StabilitySearch::Known known(Chain& c, double dt);
  /// Seconds per trial so far: a slower search's trials start first.
  static double priority(const Chain& c);

  const Scene& scene_;
  Options options_;
  std::vector<Chain> chains_;
  std::vector<StabilityResult> out_;
  ChildPool pool_;
};

}  // namespace bb
