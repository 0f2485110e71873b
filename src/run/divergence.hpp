// When a run has diverged: NaN or Inf, or a body beyond what the scene allows.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.hpp"
#include "scene/state.hpp"

namespace bb {

/// Bounds derived from the scene: ten times the travel the physics can reach, ten thousand
/// times the energy it can trade, both counting what the case's impulses give (speed and
/// spin), so that an exact answer is never beyond them.
struct DivergenceBounds {
  double travel = 0.0;        ///< metres from a body's start
  double energy = 0.0;        ///< joules of |E - E(0)|
  double energy_scale = 0.0;  ///< joules the scene can plausibly trade (1e-4 of `energy`)
};

DivergenceBounds divergence_bounds(const Scene& scene);

/// Why `state`, whose total energy is `energy`, counts as diverged, or nullopt.
std::optional<std::string> divergence(const Scene& scene, const DivergenceBounds& bounds,
                                      const State& state, double initial_energy, double energy);

}  // namespace bb
