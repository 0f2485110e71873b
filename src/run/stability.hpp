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

/// One run at one step: stable means no divergence over the whole duration and energy never
/// above its start by more than (energy_factor - 1) energy scales.
struct StabilityTrial {
  bool stable = false;
  std::string reason;  ///< why not, when unstable
};
StabilityTrial try_step(const Backend& backend, const Scene& scene, double dt);

/// Bisects in log dt until the bracket is within 0.1 percent (at most 40 trials).
StabilityResult find_stability(const Backend& backend, const Scene& scene);

/// Every course variant and engine of the case, `backends` filtering by name when not empty;
/// backends in parallel on `jobs` threads. `on_done` is called after each backend.
std::vector<StabilityResult> find_stability_all(
    const Scene& scene, const Registry& registry, const std::vector<std::string>& backends,
    int jobs, const std::function<void(const std::string&)>& on_done = nullptr);

}  // namespace bb
