// A case's [[sweep]]: the whole case run again at each value of one parameter, every
// backend at report_dt, to show how a result moves as the parameter does (predictability,
// thresholds); with two [[sweep]]s, a map: the case at every pair of their values. Each
// point runs in its own child process, `jobs` of them at once, and each of its runs in a
// child of that child, as a case's runs do.
#pragma once

#include <functional>
#include <string>

#include "run/case_runner.hpp"

namespace bb {

/// The case at one value of its sweep: that value set, report_dt its only step, and no
/// sweep, gates or claims of its own.
Scene sweep_point_scene(const Scene& scene, double value);

/// The unit of a shard (shard.hpp) that a sweep's point at `value` is.
std::string sweep_point_unit(double value);

/// The case at one point of its map: the first [[sweep]]'s `value` and the second's
/// `second` set (a "dt" axis makes that step report_dt), as sweep_point_scene.
Scene map_point_scene(const Scene& scene, double value, double second);

/// The points of the case's sweep or map, in their order (SweepResults), without runs.
std::vector<SweepPoint> sweep_points(const Scene& scene);

/// The unit of a shard that `point` of the case's sweep or map is.
std::string point_unit(const Scene& scene, const SweepPoint& point);

/// Refuses (CaseError at the second [[sweep]]) a map whose runs on this machine (the
/// reference, its self-check and each backend `options` ask for that can run the case, at
/// every point; with a shard, its share) are more than kMaxMapRunsPerMachine, with the count
/// and how to shard it.
void check_map_size(const Scene& scene, const RunOptions& options);

/// Runs every value of `scene.sweep` (those of the options' shard); `progress` is called
/// once per point run.
SweepResults run_sweep(const Scene& scene, const Registry& registry, const RunOptions& options,
                       const std::function<void(const std::string&)>& progress);

}  // namespace bb
