// The cost pass: time spent in step() only, serial, repeated, median reported.
#pragma once

#include "run/results.hpp"

namespace bb {

struct CostOptions {
  double min_seconds = 0.05;  ///< keep repeating until the timed total reaches this
  int min_repeats = 3;
  int max_repeats = 1000;
};

/// Median seconds that `steps` calls of step() take in a fresh run, over repeats.
struct Timing {
  double median_seconds = 0.0;
  int repeats = 0;
};
Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options);

}  // namespace bb
