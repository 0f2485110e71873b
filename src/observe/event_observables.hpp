// The observables that come from a run's events rather than its samples: contact times,
// apex heights, the velocity after the first contact, the deepest overlap, the period of a
// swing, a fall, the springs' largest stretch, and what the first collision between two
// bodies did to momentum and kinetic energy. Each is a MeasureFn (observable_measure.hpp);
// the registry maps the kinds to them.
#pragma once

#include "observe/observable_measure.hpp"

namespace bb {

/// "not measured: ...": why the contact observables of `body` have no value where it made no
/// contact the observer can time but one it saw only as a push (BodyEvents::
/// unresolved_contact): what was seen, the overlap and the slowing. nullopt where there was
/// no such push, or `with_moving` and it was not with a moving body.
std::optional<std::string> unmeasured_contact(const Scene& scene, int body,
                                              const BodyEvents& events, bool with_moving);

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
/// A coordinate swinging less than this share of the widest swing of a body's centre (the
/// largest way between two turns in a row: a fall or a drift is no swing) is not where its
/// cycle is read (a wobble, an engine's rounding).
inline constexpr double kSwingShare = 0.1;

/// A coordinate's turn back by less than this share of its swing from the turn before is a
/// wobble on the swing (a stiff spring's, a float engine's rounding), not a turn of its own.
inline constexpr double kTurnShare = 1e-3;

/// A lowest point within this share of a coordinate's swing of one a cycle before is the
/// same point of the swing come back (lower or higher as the swing grows or dies); farther,
/// it is another point of a longer cycle (a pendulum past 90 degrees swings across to -1,
/// back to -1 and to sin(theta0) in one cycle).
inline constexpr double kPlaceShare = 0.5;

/// period (s): the motion's own cycle. For a hinged body, the mean time between upward zero
/// crossings of its spin about the hinge's axis (its angle's cycle). Otherwise, per axis
/// whose coordinate swings at least kSwingShare as wide as the widest,
/// the cycle of its lowest points (its velocity rising through zero; wobbles smaller than
/// kTurnShare of its swing left out): the mean span of the least number of them after which
/// the swing comes back to the same point; the longest of these. A pendulum's height goes
/// through two cycles in each of its swing's, and past 90 degrees its swing across has three
/// lowest points in one: neither is its period.
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
