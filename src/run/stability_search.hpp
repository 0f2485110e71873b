// The stability search as a sequence of trials: bisection in log dt for the first threshold,
// then probes below the step found, and every change of verdict between neighbouring trials
// narrowed down, so that stability that is not monotone in dt shows as bands.
#pragma once

#include <functional>
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
  /// What is known of a step's trial, when looking ahead.
  enum class Known { Nothing, Running, Stable, Unstable };
  /// Steps next() may ask for after the trials known or running end, up to `count`, none
  /// of them known or running, nearest first: each running step's verdict is supposed either
  /// way (a known one is taken as it is), kLookAhead steps deep. Tried on cores that would
  /// be idle, they shorten a long search without changing which trials it records.
  std::vector<double> likely_next(int count, const std::function<Known(double)>& known) const;
  /// How many supposed verdicts deep likely_next() looks.
  static constexpr int kLookAhead = 3;
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
