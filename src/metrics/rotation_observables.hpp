// Observables of a turning body (seed section 5).
#pragma once

#include <optional>

#include "metrics/observables.hpp"

namespace bb {

/// The value of `observe` on `trajectory`, or nullopt when its kind is not one of these:
/// - flips: how many times the body turned over about its middle principal axis (the
///   tennis-racket flip): sign changes, over the samples, of that axis's direction
///   against the direction of the body's initial angular momentum. A note for a body
///   without a distinct middle axis (a sphere, a cube, a point).
std::optional<ObservableValue> measure_rotation(const Scene& scene, const Observe& observe,
                                                const Trajectory& trajectory);

}  // namespace bb
