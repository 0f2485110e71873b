// Observables of a turning body (seed section 5).
#pragma once

#include <optional>

#include "metrics/observables.hpp"

namespace bb {

/// The value of `observe` on `trajectory`, or nullopt when its kind is not one of these:
/// - final_angle (degrees): the turn about z from the start to the end, whole turns
///   included: unwrapped at every step from the spin (StepObserver, next_turn), not over
///   the samples (2D cases);
/// - post_angular_velocity (rad/s): the spin at the first sample after the body's first
///   push or contact;
/// - flips: how many times the body turned over about its middle principal axis (the
///   tennis-racket flip): over the samples, how often that axis went from pointing
///   along the body's initial angular momentum (a cosine above 0.5) to against it (below
///   -0.5), or back. A note for a body
///   without a distinct middle axis (a sphere, a cube, a point).
std::optional<ObservableValue> measure_rotation(const Scene& scene, const Observe& observe,
                                                const Trajectory& trajectory);

}  // namespace bb
