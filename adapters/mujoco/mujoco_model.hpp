// The MJCF model of a World for MuJoCo, written in memory: per moving body a free joint in
// 3D, or two slide joints (x, y) and a hinge (z) in 2D, its mass and principal inertia; a
// fixed body welded to the world. With a ground, each body's shape and its pair with the
// ground (frictionless so far); bodies do not touch each other yet.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace bb {

/// The time scale of a contact, s: 1 / its natural frequency, MuJoCo's default time constant;
/// never below two steps, as MuJoCo's own `refsafe` keeps its standard form (a contact
/// stiffer than the step resolves throws the body off).
inline constexpr double kMujocoContactTime = 0.02;
/// The contacts' impedance, MuJoCo's largest: the reference acceleration is followed.
inline constexpr double kMujocoImpedance = 0.9999;

/// A ground contact in MuJoCo's direct form: x'' = -damping x' - stiffness x (1/s^2, 1/s),
/// whose damping ratio gives the case's restitution.
struct MujocoContact {
  double stiffness, damping, damping_ratio;
};
MujocoContact mujoco_contact(double restitution, double dt);

/// The model's XML at step `dt`.
std::string mujoco_model_xml(const World& world, double dt);

}  // namespace bb
