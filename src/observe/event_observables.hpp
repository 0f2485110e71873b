// The observables that come from a run's events rather than its samples: contact times,
// apex heights, the velocity after the first contact, the deepest overlap, the period of a
// swing, a fall, the springs' largest stretch, and what the first collision between two
// bodies did to momentum and kinetic energy. Each is a MeasureFn (observable_measure.hpp);
// the registry maps the kinds to them.
#pragma once

#include "observe/observable_measure.hpp"

namespace bb {

/// contact_time (s): the n-th contact of the body.
ObservableValue measure_contact_time(const Scene&, const Observe&, const Trajectory&,
                                     const EventTrace*);
/// bounce_apex (m): the centre's height above the ground at the n-th apex after a contact.
ObservableValue measure_bounce_apex(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
/// post_velocity (m/s): the speed right after the body's first contact.
ObservableValue measure_post_velocity(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);
/// post_normal_velocity (m/s): that velocity along the contact's normal, which points away
/// from what the body touched: positive for a body that bounced back or was pushed off,
/// negative for one that went on into where the other was.
ObservableValue measure_post_normal_velocity(const Scene&, const Observe&, const Trajectory&,
                                             const EventTrace*);
/// max_penetration (m): the deepest overlap of the body's contacts.
ObservableValue measure_max_penetration(const Scene&, const Observe&, const Trajectory&,
                                        const EventTrace*);
/// period (s): the mean time between upward zero crossings of the velocity along the axis
/// it crosses zero most often on.
ObservableValue measure_period(const Scene&, const Observe&, const Trajectory&, const EventTrace*);
/// fall_time (s): the first time the centre came within kFallAllowance of lying flat.
ObservableValue measure_fall_time(const Scene&, const Observe&, const Trajectory&,
                                  const EventTrace*);
/// max_stretch: the largest relative stretch of any spring with a rest length.
ObservableValue measure_max_stretch(const Scene&, const Observe&, const Trajectory&,
                                    const EventTrace*);
/// momentum_change (N s): |change of total momentum| across the first collision between two
/// moving bodies, gravity's impulse over the step removed.
ObservableValue measure_momentum_change(const Scene&, const Observe&, const Trajectory&,
                                        const EventTrace*);
/// angular_momentum_change (N m s): the same for angular momentum about the world's origin,
/// gravity's angular impulse removed.
ObservableValue measure_angular_momentum_change(const Scene&, const Observe&, const Trajectory&,
                                                const EventTrace*);
/// energy_change (J): the kinetic energy, spins included, after that collision less before.
ObservableValue measure_energy_change(const Scene&, const Observe&, const Trajectory&,
                                      const EventTrace*);

}  // namespace bb
