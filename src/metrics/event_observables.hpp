// The observables that come from a run's events rather than its samples: contact times,
// apex heights, the velocity after the first contact, the deepest overlap, and what the
// first collision between two bodies did to momentum and kinetic energy.
#pragma once

#include <optional>

#include "metrics/observables.hpp"
#include "scene/event_trace.hpp"

namespace bb {

/// The value of `observe` from `events`, or nullopt when its kind is not an event kind.
/// contact_time (s), bounce_apex (m, the centre's height above the ground), post_velocity
/// (m/s, the speed right after the body's first contact), post_normal_velocity (m/s, that
/// velocity along the contact's normal, which points away from what the body touched:
/// positive for a body that bounced back or was pushed off, negative for one that went on
/// into where the other was), max_penetration (m), fall_time
/// (s, the first time the centre came within kFallAllowance of lying flat: a wall down),
/// momentum_change (N s, |change of total momentum| across the first collision between two
/// moving bodies, gravity's impulse over the step removed), angular_momentum_change (N m s,
/// the same for angular momentum about the world's origin, gravity's angular impulse
/// removed), energy_change (J, the kinetic energy, spins included, after that collision
/// less before it).
std::optional<ObservableValue> measure_event(const Observe& observe, const EventTrace& events);

}  // namespace bb
