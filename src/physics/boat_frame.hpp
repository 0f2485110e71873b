// A boat's own directions on the water, seen from above: its heading (the body's x axis) and
// the direction across it to port (the body's y axis), from its orientation.
#pragma once

#include "model/vec3.hpp"

namespace bb {

struct BoatFrame {
  Vec3 ahead;   ///< unit, the heading
  Vec3 across;  ///< unit, to port (left of the heading)
};

inline BoatFrame boat_frame(const Quat& orientation) {
  return {orientation * Vec3(1.0, 0.0, 0.0), orientation * Vec3(0.0, 1.0, 0.0)};
}

}  // namespace bb
