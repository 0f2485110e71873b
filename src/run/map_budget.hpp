// A map's budget: how many runs it makes on this machine, said before any work, and how long
// its points still to run will take, estimated from the first of them once it has run (the
// one with the most steps): its time outside its steps (a process's start, the scene's setup)
// once per point, its steps' time in proportion to each point's steps, over the jobs.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "run/case_runner.hpp"

namespace bb {

/// A map's size for `options` on this machine.
struct MapSize {
  std::size_t rows = 0, columns = 0;  ///< the first [[sweep]]'s values, the second's
  std::size_t points_here = 0;        ///< the points of this machine's share (all, unsharded)
  /// The reference, its self-check and each backend `options` ask for that can run the case.
  int runs_per_point = 0;
  double runs() const { return static_cast<double>(rows * columns) * runs_per_point; }
  double runs_here() const { return static_cast<double>(points_here) * runs_per_point; }
};
MapSize map_size(const Scene& scene, const RunOptions& options);

/// What is said before any work: "<case>: a map of P x Q points of R runs each: N runs on
/// this machine, ...". "" for a case without a map, or when `options` run no sweep.
std::string map_size_text(const Scene& scene, const RunOptions& options);

/// The steps of each run at `point`: the case's duration over the point's step.
double point_steps(const Scene& scene, const SweepPoint& point);

/// The estimate of the points still to run, from the first of them.
struct MapEstimate {
  double first_seconds = 0.0;       ///< the first point's wall time
  double first_step_seconds = 0.0;  ///< of which in its runs' steps
  std::size_t rest_points = 0;
  double rest_seconds = 0.0;  ///< the others' estimated wall time over `jobs`
  int jobs = 1;
};
MapEstimate estimate_map(const Scene& scene, const SweepPoint& first, double first_seconds,
                         const std::vector<const SweepPoint*>& rest, int jobs);

/// The estimate said once the first point has run, naming what it is made from.
std::string map_estimate_text(const Scene& scene, const MapEstimate& estimate);

}  // namespace bb
