// The harness's vectors to Box2D's (x and y, in float).
#pragma once

#include <box2d/b2_math.h>

#include "model/vec3.hpp"

namespace bb {

inline b2Vec2 to_b2(const Vec3& v) {
  return {float(v.x()), float(v.y())};
}

}  // namespace bb
