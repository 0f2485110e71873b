// The range a vector of each kind must lie in. A finite but huge vector passes the zero
// check and then overflows (the ground normal [0, 1e160, 0] squares to infinity and the
// ground disappears; a speed of 1e300 m/s leaves nothing to plot): the loader refuses
// every vector whose norm lies outside its kind's range, saying the range.
#pragma once

#include <string>

#include "model/vec3.hpp"

namespace bb {

enum class VectorKind {
  Position,  ///< body positions, the ground's point, grid origin, hinge anchors, impulse points
  Velocity,  ///< body velocities
  AngularVelocity,  ///< body spins
  Direction,        ///< the ground's normal, hinge axes: only the direction counts
  Gravity,
  Wind,     ///< the air's wind
  Force,    ///< a box's wind_force, a body's force
  Torque,   ///< a body's torque
  Impulse,  ///< an [[impulse]]
};

/// The range of a body's sizes (a sphere's radius, a box's half extents, a grid's spacing, a
/// spring's rest length at most): a micrometre to a thousand kilometres. ODE aborts on a
/// ball of 1e-200 m (its inertia rounds to 0) and every engine on one of 1e200 m.
inline constexpr double kLeastSize = 1e-6, kMostSize = 1e6;
/// The range of a moving body's or particle's mass: a microgram to a million tonnes.
inline constexpr double kLeastMass = 1e-9, kMostMass = 1e9;
/// The largest spring stiffness (N/m) and damping (N s/m).
inline constexpr double kMostSpringConstant = 1e9;

struct VectorLimit {
  double least = 0.0;  ///< smallest norm allowed (directions only)
  double most = 0.0;   ///< largest norm allowed
  const char* unit;    ///< "m", "m/s", ... ("" for a direction)
  const char* what;    ///< "a position", "a velocity", ...
};

/// The range of `kind`: positions within 1e6 m of the origin (where a double still resolves
/// the 1e-9 m overlap rounding), velocities and winds up to 1e5 m/s, spins up to 1e5 rad/s,
/// gravity up to 1e4 m/s^2 (a thousand g), forces up to 1e9 N, torques up to 1e9 N m, impulses up
/// to 1e9 N s, and directions between 1e-9 and 1e9 long (their squares neither underflow nor
/// overflow).
const VectorLimit& vector_limit(VectorKind kind);

/// Why `v` cannot be a vector of `kind` ("has a norm of 1e+160 m; a position is at most
/// 1e+06 m from the origin"), or "" when it can.
std::string vector_limit_problem(VectorKind kind, const Vec3& v);

}  // namespace bb
