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
inline ConstVec spin(const double* y, int i) {
  return ConstVec(y + at(i) + 10);
}

/// Contact distance below which a second contact counts as simultaneous, metres.
inline constexpr double kSimultaneousGap = 1e-9;

inline double inverse_mass(const Body& b) {
  return b.fixed ? 0.0 : 1.0 / b.mass;
}

}  // namespace bb::state_view
