// The cost pass: time spent in step() only, serial, repeated, median reported.
#pragma once

#include "run/results.hpp"

namespace bb {

struct CostOptions {
  double min_seconds = 0.005;  ///< keep repeating until the timed total reaches this
  int min_repeats = 3;         ///< and until this many repeats, unless...
  /// ...the timed total already reaches this: a tenth of a second of steps averages out
  /// the scheduler's noise.
  double enough_seconds = 0.1;
  /// A repeat stops timing after this many seconds of calls and the rest of the run is
  /// extrapolated from them: a grid's engine at its finest dt would take seconds, each
  /// step much like the others.
  double max_seconds_per_repeat = 0.01;
  int max_repeats = 30;  ///< the median of thirty is steady; each repeat builds the scene anew
};

/// Median seconds that `steps` calls of step() take in a fresh run, over repeats.
struct Timing {
  double median_seconds = 0.0;
  int repeats = 0;
  long calls_timed = 0;  ///< most calls timed in one repeat (`steps` unless cut short)
};
Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options);

}  // namespace bb
