// MuJoCo, named by the design (libmujoco-dev is in Debian) but without an adapter yet: it
// has a row, saying so, only when a user asks for it by name, and no settings keys.
#pragma once

#include "scene/engine_catalogue.hpp"

namespace bb {

inline EngineDescription mujoco_engine() {
  return {"mujoco", {"mujoco"}, {}, false};
}

}  // namespace bb
