// Where the forces are evaluated: every body's position, velocity, orientation and spin, as
// arrays of the scene's body count. Each caller keeps its state its own way (the course in
// separate arrays, the reference in one vector, an engine in its bodies); this view is what
// they hand the force model, so that a force is written once for all of them.
#pragma once

#include "model/vec3.hpp"

namespace bb {

struct BodyStates {
  const Vec3* position = nullptr;     ///< metres
  const Vec3* velocity = nullptr;     ///< metres per second
  const Quat* orientation = nullptr;  ///< unit quaternions
  const Vec3* spin = nullptr;         ///< radians per second, world frame
};

}  // namespace bb
