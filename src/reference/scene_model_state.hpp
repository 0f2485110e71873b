// Views into the reference's integrated state: where each part of body i sits in the flat
// vector GSL steps (SceneModel::kPerBody numbers per body), shared by the equations of
// motion (scene_model.cpp) and the events and resets (scene_model_events.cpp).
#pragma once

#include <Eigen/Geometry>

#include "reference/scene_model.hpp"

namespace bb::state_view {

using Eigen::Quaterniond;
using Eigen::Vector3d;
using ConstVec = Eigen::Map<const Vector3d>;
using Vec = Eigen::Map<Vector3d>;

inline std::size_t at(int i) {
  return SceneModel::kPerBody * static_cast<std::size_t>(i);
}
inline ConstVec position(const double* y, int i) {
  return ConstVec(y + at(i));
}
inline ConstVec velocity(const double* y, int i) {
  return ConstVec(y + at(i) + 3);
}
inline Quaterniond orientation(const double* y, int i) {
  const double* q = y + at(i) + 6;
  return {q[0], q[1], q[2], q[3]};
}
/// The angular velocity in the body's own frame, as the state holds it: Euler's equations
/// are integrated there, where the inertia is constant and diagonal.
inline ConstVec body_spin(const double* y, int i) {
  return ConstVec(y + at(i) + 10);
}
/// The angular velocity in the world frame (rad/s).
inline Vector3d spin(const double* y, int i) {
  return orientation(y, i).normalized() * Vector3d(body_spin(y, i));
}
/// Sets body i's angular velocity to `world` (rad/s, world frame).
inline void set_spin(double* y, int i, const Vector3d& world) {
  Eigen::Map<Vector3d>(y + at(i) + 10) = orientation(y, i).normalized().conjugate() * world;
}

/// Body i's state as the runner reads it: orientation normalised, spin in the world frame.
inline BodyState body_state(const double* y, int i) {
  BodyState s;
  s.position = position(y, i);
  s.velocity = velocity(y, i);
  s.orientation = orientation(y, i).normalized();
  s.angular_velocity = spin(y, i);
  return s;
}

/// Contact distance below which a second contact counts as simultaneous, metres.
inline constexpr double kSimultaneousGap = 1e-9;

inline double inverse_mass(const Body& b) {
  return b.fixed ? 0.0 : 1.0 / b.mass;
}

}  // namespace bb::state_view
