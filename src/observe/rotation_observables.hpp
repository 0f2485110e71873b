// Observables of a turning body (seed section 5), each a MeasureFn (observable_measure.hpp).
#pragma once

#include "observe/observable_measure.hpp"

namespace bb {

/// final_angle (degrees): the turn about z from the start to the end, whole turns included:
/// unwrapped at every step from the spin (StepObserver, next_turn), not over the samples
/// (2D cases).
ObservableValue measure_final_angle(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
/// post_angular_velocity (rad/s): the spin at the first sample after the body's first push
/// or contact, signed about the observe's axis (+z in 2D unless it says -z): positive for a
/// turn counterclockwise seen from the axis's tip.
ObservableValue measure_post_angular_velocity(const Scene&, const Observe&, const Trajectory&,
                                              const EventTrace*);
/// flips: how many times the body turned over about its middle principal axis (the
/// tennis-racket flip): over the samples, how often that axis went from pointing along the
/// body's initial angular momentum (a cosine above 0.5) to against it (below -0.5), or
/// back. A note for a body without a distinct middle axis (a sphere, a cube, a point).
ObservableValue measure_flips(const Scene&, const Observe&, const Trajectory&, const EventTrace*);

}  // namespace bb
