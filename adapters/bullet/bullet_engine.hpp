// Bullet as the harness knows it: one settings table, two backends (double and single
// precision builds of the same adapter), and its keys with their defaults.
#pragma once

#include "scene/engine_catalogue.hpp"

namespace bb {

inline EngineDescription bullet_engine() {
  const std::string e = "bullet";
  return {e,
          {"bullet", "bullet-float"},
          {{e, "solver_iterations", KeyKind::Integer, 10, "sequential-impulse iterations"},
           {e, "erp", KeyKind::Number, 0.2, "error reduction per step, contacts and joints"},
           {e, "split_impulse", KeyKind::Boolean, 1, "split-impulse position correction"},
           {e, "linear_damping", KeyKind::Number, 0.0, "built-in linear damping, 1/s"},
           {e, "angular_damping", KeyKind::Number, 0.0, "built-in angular damping, 1/s"}}};
}

}  // namespace bb
