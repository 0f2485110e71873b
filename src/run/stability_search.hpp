// The stability search as a sequence of trials: bisection in log dt for the first threshold,
// then probes below the step found, and every change of verdict between neighbouring trials
// narrowed down, so that stability that is not monotone in dt shows as bands.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

class StabilitySearch {
 public:
  /// Fractions of the step found by bisection that are probed below it.
  static constexpr double kProbes[] = {0.9, 0.75, 0.5, 0.25};
  /// No search takes more trials than this.
  static constexpr int kMaxTrials = 60;

  StabilitySearch(double dt_min, double dt_max) : dt_min_(dt_min), dt_max_(dt_max) {}
  /// The step to try next, or nullopt when the search is over. First dt_max; dt_min while
  /// the smallest step tried is unstable; then, lowest first, every pair of neighbouring
  /// trials with different verdicts is halved in log dt until within 0.1 percent (the
  /// lowest pair, which sets the largest safe step) or 1 percent (the others); once the first
  /// bracket is narrowed, the probes below the largest stable step found.
  std::optional<double> next() const;
  void record(double dt, const StabilityTrial& trial);
  /// Status, steps, bands and reasons from the trials so far.
  void fill(StabilityResult& result) const;

 private:
  struct Tried {
    double dt;
    StabilityTrial trial;
  };
  std::optional<double> narrowing() const;
  bool needs_bottom() const;
  bool all_unstable() const;
  void queue_probes();

  double dt_min_, dt_max_;
  std::vector<Tried> tried_;    ///< sorted by dt
  std::vector<double> probes_;  ///< still to try
  bool probed_ = false;
};

}  // namespace bb
