// A case's [[sweep]]: the whole case run again at each value of one parameter, every
// backend at report_dt, to show how a result moves as the parameter does (predictability,
// thresholds). Each point runs in its own child process, `jobs` of them at once, and each
// of its runs in a child of that child, as a case's runs do.
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

/// Runs every value of `scene.sweep` (those of the options' shard); `progress` is called
/// once per point run.
SweepResults run_sweep(const Scene& scene, const Registry& registry, const RunOptions& options,
                       const std::function<void(const std::string&)>& progress);

}  // namespace bb
