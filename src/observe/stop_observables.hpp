// The observables of a body sliding on the ground (seed section 6): when and where it
// stopped, how far it crept after the reference had stopped it, and its final velocity.
#pragma once

#include <optional>

#include "observe/observable_measure.hpp"

namespace bb {

/// stop_time (s, from the start of the run): the end of the body's last motion along the
/// ground, where its velocity along the ground reached zero or turned back. A motion begins
/// at the start (a body moving there) or where a body at rest is set moving (a push, static
/// friction giving way); a body at rest throughout stopped at t = 0; one whose last motion
/// has not ended never stops in the run.
ObservableValue measure_stop_time(const Scene&, const Observe&, const Trajectory&,
                                  const EventTrace*);
/// stop_distance (m): how far along the ground that last motion took it, from where it
/// began to the stop.
ObservableValue measure_stop_distance(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);
/// rest_creep (m): how far along the ground it moved from the later of the reference's stop
/// and its own to the end of the run (the seed's crawl); `reference` holds the reference's
/// events (nullptr: none to measure from); a note when the reference never stops the body.
ObservableValue measure_rest_creep(const Scene&, const Observe&, const Trajectory&,
                                   const EventTrace* reference);
/// final_velocity (m/s): its velocity at the end along its direction of sliding (its first
/// push, else downhill, else +x), negative when it ended going back.
ObservableValue measure_final_velocity(const Scene&, const Observe&, const Trajectory&,
                                       const EventTrace*);

/// A body whose stop is observed is at rest while it moves along the ground slower than its
/// rest speed: the case's `rest_speed`, else this share of the fastest it has moved along
/// the ground (or of |g| dt, for a body that has not moved). Slower than that, a body only
/// wobbles or creeps (an engine's rounding, its friction's slow give): it has not set off,
/// and what it moves is its rest_creep. A boat slower than its rest speed (the same share of
/// the wind's speed or of its own fastest) has no drift angle.
inline constexpr double kRestShare = 1e-3;

/// The rest speed (m/s) a case gives `body` on one of its [[observe]] (`rest_speed`): below
/// it the body is at rest; nullopt where none gives one (each kind's default applies).
std::optional<double> stated_rest_speed(const Scene& scene, int body);

/// The unit direction final_velocity is measured along for `body`: its initial velocity
/// along the ground, else its first impulse's, else downhill along the ground, else +x.
Vec3 sliding_direction(const Scene& scene, int body);

}  // namespace bb
