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
  double max_seconds_per_repeat = 0.005;
  int max_repeats = 30;  ///< the median of thirty is steady; each repeat builds the scene anew
  /// Once min_repeats are done, repeats stop when they took this many seconds of wall time,
  /// building the scene included: a scene slow to build (an engine compiling its model) and
  /// quick to run is not built thirty times for a few milliseconds of steps.
  double max_wall_seconds = 0.02;
};

/// Seconds that `steps` calls of step() take in a fresh run: median, fastest and slowest
/// over repeats.
struct Timing {
  double median_seconds = 0.0;
  int repeats = 0;
  long calls_timed = 0;  ///< most calls timed in one repeat (`steps` unless cut short)
  double min_seconds = 0.0;
  double max_seconds = 0.0;
  /// Seconds of calls timed over every repeat: the steps this measurement ran.
  double timed_seconds = 0.0;
  /// Scenes built: one per repeat, or one in all where the simulation rewinds.
  int builds = 0;
};
Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options);

}  // namespace bb

namespace bb {

/// A cost whose median repeat took more than this many times its fastest was timed on a
/// busy machine: the median it reports is inflated by whatever else was running.
inline constexpr double kBusyMedianOverMin = 1.25;

/// Whether `cost` says the machine was busy while it was timed: three repeats or more (fewer
/// have no spread to read) and a median more than kBusyMedianOverMin times the fastest.
bool timed_on_a_busy_machine(const Cost& cost);

}  // namespace bb
