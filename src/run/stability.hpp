// The largest stable step per backend, by bisection between the case's dt_min and dt_max.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "run/registry.hpp"
#include "run/results.hpp"
#include "scene/scene.hpp"

namespace bb {

/// One run at one step: stable means bounded: no divergence over the whole duration, and
/// the energy's rise above its start not still growing by the run's end (its largest rise in
/// the last quarter at most growth_factor times that in the second quarter).
struct StabilityTrial {
  bool stable = false;
  std::string reason;  ///< why not, when unstable
};
StabilityTrial try_step(const Backend& backend, const Scene& scene, double dt);

/// The search as a sequence of trials: the largest step, the smallest, then halving the
/// bracket in log dt until it is within 0.1 percent (at most 40 trials in all).
class Bisection {
 public:
  Bisection(double dt_min, double dt_max) : lo_(dt_min), hi_(dt_max) {}
  /// The step to try next, or nullopt when the search is over.
  std::optional<double> next() const;
  void record(double dt, const StabilityTrial& trial);
  /// Status, bracket and reason so far.
  void fill(StabilityResult& result) const;

 private:
  enum class Phase { Top, Bottom, Halving, Done };
  Phase phase_ = Phase::Top;
  double lo_, hi_;
  int trials_ = 0;
  std::string status_;
  std::string reason_;
};

/// The whole search for one backend, in this process.
StabilityResult find_stability(const Backend& backend, const Scene& scene);

/// Every course variant and engine of the case (`backends` filters by name when not empty),
/// each trial in its own child process with a time limit; backends searched in parallel on
/// `jobs` processes. `on_done` is called after each backend's search.
std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done = nullptr,
    bool isolation = true, double timeout = 0.0);

}  // namespace bb
