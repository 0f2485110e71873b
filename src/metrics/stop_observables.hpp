// The observables of a body sliding on the ground (seed section 6): when and where it
// stopped, how far it crept after the reference had stopped it, and its final velocity.
#pragma once

#include <optional>

#include "metrics/observables.hpp"

namespace bb {

/// The value of `observe` on `trajectory`, or nullopt when its kind is not one of these:
/// - stop_time (s): the first time the body's velocity along the ground reached zero or
///   turned back after it slid (0: held at rest from the start);
/// - stop_distance (m): how far along the ground it went from its start to that stop;
/// - rest_creep (m): how far along the ground it moved from the later of the reference's
///   stop and its own to the end of the run (the seed's crawl); `reference` holds the
///   reference's events (nullptr: none to measure from); a note when the reference never
///   stops the body;
/// - final_velocity (m/s): its velocity at the end along its direction of sliding (its
///   first push, else downhill, else +x), negative when it ended going back.
std::optional<ObservableValue> measure_stop(const Scene& scene, const Observe& observe,
                                            const Trajectory& trajectory,
                                            const EventTrace* reference);

/// The unit direction final_velocity is measured along for `body`: its initial velocity
/// along the ground, else its first impulse's, else downhill along the ground, else +x.
Vec3 sliding_direction(const Scene& scene, int body);

}  // namespace bb
