// The range a vector of each kind must lie in. A finite but huge vector passes the zero
// check and then overflows (the ground normal [0, 1e160, 0] squares to infinity and the
// ground disappears; a speed of 1e300 m/s leaves nothing to plot): the loader refuses
// every vector whose norm lies outside its kind's range, saying the range.
#pragma once

#include <string>

#include "scene/vec3.hpp"

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
