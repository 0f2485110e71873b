// When a run has diverged: NaN or Inf, or a body or the energy beyond what the scene can
// give (physics/energy_scale.hpp): a run that blew up is never `ok`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/trajectory.hpp"
#include "model/state.hpp"
#include "physics/energy_scale.hpp"
#include "study/scene.hpp"

namespace bb {

/// A run's total energy may rise above its start by at most this many times the scene's
/// energy scale, and a body move at most the square root of it times faster or farther than
/// the scene can make it (the same bound on its kinetic energy alone): past it the run's
/// numbers say nothing of the scene's motion, and it is `diverged`.
inline constexpr double kBlowUpEnergy = 100.0;
/// The same factor for a stability trial, which only stops there: whether the energy stays
/// bounded is the growth judge's question (energy_growth.hpp), and a bounded swing may pass
/// kBlowUpEnergy (semi-implicit Euler at 0.99 of its limit 2 / omega swings a mode's energy by
/// (1 + h omega / 2) / (1 - h omega / 2) = 199 times) and still be stable.
inline constexpr double kTrialStopEnergy = 1e4;

/// Bounds derived from the scene, all counting what the case's impulses and forces give.
struct DivergenceBounds {
  EnergyScale scale;           ///< what the scene can put into motion over the run
  double factor = 0.0;         ///< kBlowUpEnergy or kTrialStopEnergy
  double energy = 0.0;         ///< J: the largest rise of the total energy, `factor` scales
  std::vector<double> speed;   ///< per body, m/s: sqrt(factor) times the fastest it can move
  std::vector<double> travel;  ///< per body, m from its start: sqrt(factor) times its farthest
};

/// Over the case's duration, at kBlowUpEnergy; or over `duration` seconds at `factor` (a
/// stability trial runs longer, and stops at kTrialStopEnergy).
DivergenceBounds divergence_bounds(const Scene& scene);
DivergenceBounds divergence_bounds(const Scene& scene, double duration, double factor);

/// A body may go at most this many times the size of the reference's extent (the box
/// around everywhere its bodies go) outside it.
inline constexpr double kBeyondReference = 10.0;

/// When and why a run left the reference's extent by more than kBeyondReference times its
/// size: the first such sample of `run` (samples as the reference's), or nullopt.
struct Beyond {
  double time = 0.0;  ///< simulated seconds
  std::string reason;
};
std::optional<Beyond> beyond_reference(const Scene& scene, const Trajectory& run,
                                       const Trajectory& reference);

/// Why `state`, whose total energy is `energy` (the run started at `initial_energy`),
/// counts as diverged, or nullopt.
std::optional<std::string> divergence(const Scene& scene, const DivergenceBounds& bounds,
                                      const State& state, double initial_energy, double energy);

}  // namespace bb
