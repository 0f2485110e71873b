// The largest stable step per backend, searched between the case's dt_min and dt_max
// (stability_search.hpp), with the bands where stability is not monotone in dt.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "run/registry.hpp"
#include "run/results.hpp"
#include "run/run_cache.hpp"
#include "run/stability_search.hpp"
#include "study/scene.hpp"

namespace bb {

/// One run at one step, `steps` long (StabilityWatch::trial_steps() when 0), judged by its
/// energy's growth after the last impulse (which may add energy at once) over
/// kGrowthWindows windows: see energy_growth.hpp.
StabilityTrial try_step(const Backend& backend, const Scene& scene, double dt, long steps = 0);

/// How many times longer a trial runs, when its step is past the theory's limit and the
/// usual trial found it stable: growth slow enough to stay small over the case's duration
/// (an explicit Euler chain's stiffest mode, barely excited) shows over a longer run.
inline constexpr long kTheoryProbeFactor = 10;

/// try_step(); where `theory` (s, the theory's limit for the backend) lies below `dt` and the
/// trial reads stable, the verdict of a trial kTheoryProbeFactor times longer instead, which
/// says so.
StabilityTrial judge_step(const Backend& backend, const Scene& scene, double dt,
                          std::optional<double> theory);

/// The theory's largest stable step (s) for the course variant named `backend` on `scene`
/// (course/stability_theory.hpp), where theory covers the scene; nullopt otherwise.
std::optional<double> theory_for(const Scene& scene, const std::string& backend);

/// The whole search for one backend, in this process.
StabilityResult find_stability(const Backend& backend, const Scene& scene);

/// Trials already judged, by backend and step: those the accuracy runs judged on their own
/// steps (RunRecord::stability_trial).
using KnownTrials = std::map<std::pair<std::string, double>, StabilityTrial>;
KnownTrials known_trials(const std::vector<RunRecord>& runs);

/// Every course variant and engine of the case (`backends` filters by name when not empty),
/// each trial in its own child process with a time limit, unless `known` or `cache` has it
/// (a trial that finished is kept in `cache`); backends
/// searched in parallel on `jobs` processes. `on_done` is called after each backend's search.
std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done = nullptr,
    bool isolation = true, double timeout = 0.0, const KnownTrials& known = {},
    RunCache* cache = nullptr);

}  // namespace bb
