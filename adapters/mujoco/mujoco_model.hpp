// The MJCF model of a World for MuJoCo, written in memory: per moving body a free joint in
// 3D, or two slide joints (x, y) and a hinge (z) in 2D, or the hinge joint of its [[hinge]];
// its mass and principal inertia; a fixed body welded to the world. Each body that can touch
// something gets its shape, and each pair of the case one <pair> (friction along both
// tangents, an elliptic cone): no contact is automatic.
#pragma once

#include <string>

#include "model/world.hpp"

namespace bb {

/// The time scale of a contact, s: 1 / its natural frequency, MuJoCo's default time constant;
/// never below two steps, as MuJoCo's own `refsafe` keeps its standard form (a contact
/// stiffer than the step resolves throws the body off).
inline constexpr double kMujocoContactTime = 0.02;
/// How far apart a contact counts, m: a body placed exactly touching the ground, as a case
/// places it, meets it with every corner from the first step, whichever way the rounding of
/// their distances falls (at 0 a resting box met it on one edge only and tipped over it).
inline constexpr double kMujocoMargin = 1e-6;
/// The contacts' impedance, MuJoCo's largest: the reference acceleration is followed.
inline constexpr double kMujocoImpedance = 0.9999;

/// A contact in MuJoCo's direct form: x'' = -damping x' - stiffness x (1/s^2, 1/s),
/// whose damping ratio gives the case's restitution.
struct MujocoContact {
  double stiffness, damping, damping_ratio;
};
MujocoContact mujoco_contact(double restitution, double dt);

/// The [[hinge]] of moving body `body`, or nullptr; throws for a body with two (MuJoCo
/// would build them, but one angle is what the adapter reads).
const Hinge* hinge_of(const World& world, std::size_t body);

/// The model's XML at step `dt`, stepped by MuJoCo's `integrator` ("Euler", "RK4" or
/// "implicit").
std::string mujoco_model_xml(const World& world, double dt, const std::string& integrator);

}  // namespace bb
