// The run state a simulation reports: per body, position, velocity, orientation and spin.
#pragma once

#include <vector>

#include "scene/vec3.hpp"

namespace bb {

struct BodyState {
  Vec3 position;                        ///< metres
  Vec3 velocity;                        ///< metres per second
  Quat orientation = Quat::Identity();  ///< unit quaternion
  Vec3 angular_velocity;                ///< radians per second, world frame
};

/// One entry per body, in the scene's body order.
using State = std::vector<BodyState>;

}  // namespace bb
