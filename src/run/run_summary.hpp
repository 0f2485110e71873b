// What a run brings back from its child process: its errors and observables measured there
// against the reference, the per-sample series the page plots, and the trajectories of only
// the bodies a plot shows. A child inherits the parent's reference at fork (one copy, shared
// by every child), so no run's whole trajectory crosses a pipe or stays in the parent.
#pragma once

#include <cstddef>

#include "run/results.hpp"

namespace bb {

/// The page's trajectory plot shows at most this many bodies.
inline constexpr std::size_t kPlottedBodies = 6;

/// Each observable of the scene on `run`, with its reference value: the formula's where
/// the kind has one, else `against`'s (when that run is ok). A backend's run that is its
/// own `against` (the fallback's finest) has none: a difference from itself says nothing.
/// The reference's own run keeps its value there, as the JSON has always given it.
void add_observables(const Scene& scene, RunRecord& run, const RunRecord& against);

/// run.energy (total energy at every sample) and, when `reference` has states,
/// run.distance (largest position distance from it over the bodies, at every sample).
void add_series(const Scene& scene, RunRecord& run, const Trajectory* reference);

/// Keeps of run.trajectory only what the page draws: at report_dt the states of the drawn
/// bodies (drawn_bodies.hpp), elsewhere none. Times and events stay.
void keep_plotted_states(const Scene& scene, RunRecord& run);
/// Keeps of every state of `run` the drawn bodies, whatever its dt (the reference's).
void keep_drawn_states(const Scene& scene, RunRecord& run);

/// run.position_scale and run.travel from the run's states: the order fit's rounding floor
/// and saturation level need them.
void record_position_scale(RunRecord& run);

/// In the child: errors, observables and series against `against` (an ok run: the
/// reference, or in the fallback of docs/design.md the backend's finest run, possibly `run`
/// itself), the position scale, then the trajectory cut to what the page draws.
void summarise_in_child(const Scene& scene, RunRecord& run, const RunRecord& against);

}  // namespace bb
