// The run state a simulation reports: per body, position, velocity, orientation and spin.
#pragma once

#include <vector>

#include "model/vec3.hpp"

namespace bb {

struct BodyState {
  Vec3 position;                        ///< metres
  Vec3 velocity;                        ///< metres per second
  Quat orientation = Quat::Identity();  ///< unit quaternion
  Vec3 angular_velocity;                ///< radians per second, world frame
  /// Radians: the turn about z (2D scenes), unwrapped at every step from the spin, starting
  /// at the initial angle in (-pi, pi]. Not a backend's: the runner keeps it from the steps
  /// it watches (0 where nothing turns in 2D, and in 3D).
  double turn = 0.0;
};

/// One entry per body, in the scene's body order.
using State = std::vector<BodyState>;

}  // namespace bb
