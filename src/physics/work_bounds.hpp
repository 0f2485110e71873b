// Bounds on the work a force term can do over a run, shared by the terms' supply() (each
// term is the home of its own bound; these are the shapes they have in common).
#pragma once

namespace bb {

/// The most work (J) a force of constant size `force` (N) does on a body of `mass` (kg) that
/// starts at `speed` (m/s), over `duration` (s), with gravity (`gravity`, m/s^2) at most
/// helping it along: F d, the distance at most v0 t + (F / m + g) t^2 / 2.
inline double push_work(double force, double mass, double speed, double gravity, double duration) {
  const double t = duration;
  return force * (speed * t + 0.5 * (force / mass + gravity) * t * t);
}

/// The most work (J) a torque of constant size `torque` (N m) does on a body whose smallest
/// moment of inertia is `moment` (kg m^2) and that starts spinning at `spin` (rad/s):
/// tau (w0 t + tau t^2 / (2 I)).
inline double turn_work(double torque, double moment, double spin, double duration) {
  const double t = duration;
  return torque * (spin * t + 0.5 * torque / moment * t * t);
}

/// The most energy (J) a uniform wind of speed `wind` (m/s) gives a body of `mass` (kg) by
/// pushing on it over `duration` (s): in the wind's frame a drag or a Magnus force does no
/// work, so the wind adds at most its own speed to the body's (m w^2 bounds the kinetic
/// energy it adds), and holding the body up against gravity (g, m/s^2) at the wind's speed
/// adds at most m g w t.
inline double wind_work(double mass, double wind, double gravity, double duration) {
  return mass * wind * (wind + gravity * duration);
}

}  // namespace bb
