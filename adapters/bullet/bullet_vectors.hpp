// The harness's vectors to Bullet's and back, in whichever precision the build uses.
#pragma once

#include <LinearMath/btVector3.h>

#include "scene/vec3.hpp"

namespace bb {

inline btVector3 to_bt(const Vec3& v) {
  return {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())};
}

inline Vec3 from_bt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace bb
