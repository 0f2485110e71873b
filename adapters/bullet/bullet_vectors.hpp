// The harness's vectors to Bullet's and back, in whichever precision the build uses.
#pragma once

#include <LinearMath/btScalar.h>
#include <LinearMath/btVector3.h>

#include <string>
#include <utility>

#include "model/vec3.hpp"

namespace bb {

inline btVector3 to_bt(const Vec3& v) {
  return {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())};
}

inline Vec3 from_bt(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

/// Library and version as the linked Bullet says: {"bullet", "3.24"}.
inline std::pair<std::string, std::string> bullet_version() {
  const int v = btGetVersion();
  return {"bullet", std::to_string(v / 100) + "." + std::to_string(v % 100)};
}

}  // namespace bb
