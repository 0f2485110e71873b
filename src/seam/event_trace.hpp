// What happened to each body during a run, at the resolution the backend has: contacts,
// apexes after them, the velocity right after the first contact, the deepest overlap.
// Fixed-step backends get it from their state at every step (StepObserver); the
// reference reports its located events exactly.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/vec3.hpp"

namespace bb {

/// A contact the per-step observer saw only as a push: at some step the two, overlapping or
/// within an engine's margin, slowed their approach, but at no step did they stop approaching (an
/// engine that resolves a hit by pushing the bodies apart over many steps, or leaves one inside the
/// other). No contact time, velocity after the contact or balance of the collision can be read off
/// it.
struct UnresolvedContact {
  int other = -1;                ///< the other body, -1 for the ground
  double time = 0.0;             ///< s, the first step at which the pair pushed
  double approach_before = 0.0;  ///< m/s, the speed of approach at the step before that
  double approach_least = 0.0;   ///< m/s, the least speed of approach since (still above 0)
};

/// Where a body's velocity along one axis crossed zero: a turn of that coordinate.
struct Turn {
  double time = 0.0;      ///< s
  double position = 0.0;  ///< m, the coordinate there
  bool lowest = false;    ///< a minimum (the velocity rose through zero), else a maximum
};

struct BodyEvents {
  std::vector<double> contact_times;  ///< seconds, every contact of the body, in order
  /// Height of the centre above the ground at each apex after a contact, metres.
  std::vector<double> apex_heights;
  std::optional<Vec3> post_velocity;  ///< m/s, right after the body's first contact
  /// Unit normal of that first contact, pointing away from what the body touched (the
  /// ground, or the other body): along it, post_velocity is positive for a body that
  /// bounced back or was pushed off.
  std::optional<Vec3> post_normal;
  double max_penetration = 0.0;  ///< metres: the deepest overlap seen (0: none)
  /// The first contact of the body seen only as a push (one with a moving body rather than
  /// the ground or a fixed body, where there are both); the reference has none.
  std::optional<UnresolvedContact> unresolved_contact;
  /// Per axis x, y, z, in time order: every turn of the coordinate (its velocity through
  /// zero either way), for a body whose period is observed.
  std::array<std::vector<Turn>, 3> turns;
  /// The times (s) the spin about the body's hinge axis crossed zero upwards (its angle at
  /// one end of its swing), for a hinged body whose period is observed.
  std::vector<double> hinge_crossings;
  /// Seconds from the start of the run: the end of the body's last motion along the ground,
  /// where its velocity along the ground reached zero or turned back; 0 for a body at rest
  /// throughout; none while its last motion goes on. A motion begins at the start or where
  /// the body leaves a rest. For bodies whose stop is observed.
  std::optional<double> stop_time;
  Vec3 stop_position;  ///< metres: where it was at stop_time
  Vec3 motion_start;   ///< metres: where the motion that ended at stop_time began
  /// Seconds: the first time the body's centre came within kFallAllowance of the height it
  /// has lying on its broadest face (a wall reaching the ground), for bodies whose fall is
  /// observed.
  std::optional<double> fall_time;
  /// Seconds: the first step after which the body's turn about z could not be counted from
  /// its spin (2D): its orientation ended more than a quarter turn away from where its spin
  /// says, as an engine's orientation update that lags a fast spin leaves it. None: every
  /// step's whole turns were counted.
  std::optional<double> turn_unclear;
};

/// Metres: how near the height of lying flat a falling body's centre must come for it to
/// have fallen; it allows for the skins and margins the engines keep between surfaces.
inline constexpr double kFallAllowance = 0.02;

/// Metres: the height above the ground of the centre of `half_extents`' box lying on its
/// broadest face, plus kFallAllowance: below it, the body has fallen.
inline double fallen_height(const Vec3& half_extents) {
  return half_extents.minCoeff() + kFallAllowance;
}

/// Momentum, angular momentum and kinetic energy of the two bodies just before and just
/// after the first contact between two moving bodies; the difference is what the
/// collision changed.
struct CollisionBalance {
  int body_a = -1;  ///< the two bodies that collide
  int body_b = -1;
  double time = 0.0;     ///< seconds
  Vec3 momentum_change;  ///< N s, of the two bodies; from steps, less gravity's impulse
  /// N m s, about the world's origin; from steps, less gravity's angular impulse
  Vec3 angular_momentum_change;
  double kinetic_energy_before = 0.0;  ///< J, with the spins' part
  /// J; from steps, less gravity's work on the two bodies over the step
  double kinetic_energy_after = 0.0;
};

/// Where a watched value of one body's state crossed zero (an observable kind's CrossingFn,
/// observe/observable_measure.hpp): a level passed going up or going down.
struct Crossing {
  double time = 0.0;    ///< s
  bool rising = false;  ///< from below zero to above it
};

struct EventTrace {
  std::vector<BodyEvents> bodies;  ///< one per body, in scene order
  /// Per observe (by its name) of a kind that watches a crossing: every crossing, in time order.
  std::map<std::string, std::vector<Crossing>> crossings;
  std::optional<CollisionBalance> first_collision;
  /// The largest relative extension (l - L) / L of any spring seen, when observed.
  std::optional<double> max_stretch;
};

}  // namespace bb
