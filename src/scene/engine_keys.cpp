#include "scene/engine_keys.hpp"

#include <stdexcept>

namespace bb {

const std::vector<EngineKey>& engine_keys() {
  static const std::vector<EngineKey> keys = {
      {"bullet", "solver_iterations", KeyKind::Integer, 10, "sequential-impulse iterations"},
      {"bullet", "erp", KeyKind::Number, 0.2, "error reduction per step, contacts and joints"},
      {"bullet", "split_impulse", KeyKind::Boolean, 1, "split-impulse position correction"},
      {"bullet", "linear_damping", KeyKind::Number, 0.0, "built-in linear damping, 1/s"},
      {"bullet", "angular_damping", KeyKind::Number, 0.0, "built-in angular damping, 1/s"},
      {"box2d", "velocity_iterations", KeyKind::Integer, 8, "velocity solver iterations"},
      {"box2d", "position_iterations", KeyKind::Integer, 3, "position solver iterations"},
      {"box2d", "linear_damping", KeyKind::Number, 0.0, "built-in linear damping, 1/s"},
      {"box2d", "angular_damping", KeyKind::Number, 0.0, "built-in angular damping, 1/s"},
      {"ode", "erp", KeyKind::Number, 0.2, "error reduction parameter"},
      {"ode", "cfm", KeyKind::Number, 1e-5, "constraint force mixing"},
      {"ode", "quick_step", KeyKind::Boolean, 0, "dWorldQuickStep instead of dWorldStep"},
      {"ode", "quick_step_iterations", KeyKind::Integer, 20, "iterations of dWorldQuickStep"},
      {"ode", "linear_damping", KeyKind::Number, 0.0, "built-in linear damping scale"},
      {"ode", "angular_damping", KeyKind::Number, 0.0, "built-in angular damping scale"},
  };
  return keys;
}

std::vector<std::string> engine_names() {
  return {"bullet", "box2d", "ode", "mujoco"};
}

const EngineKey* find_engine_key(const std::string& engine, const std::string& key) {
  for (const EngineKey& k : engine_keys())
    if (k.engine == engine && k.key == key) return &k;
  return nullptr;
}

double engine_setting(const Scene& scene, const std::string& engine, const std::string& key) {
  const EngineKey* known = find_engine_key(engine, key);
  if (known == nullptr) throw std::logic_error("no engine setting " + engine + "." + key);
  const auto e = scene.engines.find(engine);
  if (e != scene.engines.end()) {
    const auto v = e->second.find(key);
    if (v != e->second.end()) return v->second.value;
  }
  return known->fallback;
}

Settings engine_key_settings(const Scene& scene, const std::string& engine) {
  Settings out;
  for (const EngineKey& k : engine_keys()) {
    if (k.engine != engine) continue;
    const double v = engine_setting(scene, engine, k.key);
    if (k.kind == KeyKind::Boolean)
      out.push_back({k.key, v != 0.0});
    else
      out.push_back({k.key, v});
  }
  return out;
}

}  // namespace bb
