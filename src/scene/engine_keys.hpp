// The engine settings a case may give under [engines.<engine>], with their defaults.
// One table serves the loader (to reject unknown keys) and the adapters (for defaults).
#pragma once

#include <string>
#include <vector>

#include "scene/backend.hpp"
#include "scene/scene.hpp"

namespace bb {

enum class KeyKind { Number, Integer, Boolean };

struct EngineKey {
  std::string engine;  ///< "bullet", "box2d", "ode", "mujoco"
  std::string key;
  KeyKind kind;
  double fallback;      ///< the default; booleans are 0 or 1
  std::string meaning;  ///< one line, with the unit
};

/// Every known key of every engine.
const std::vector<EngineKey>& engine_keys();
/// The known engines ("bullet" covers bullet and bullet-float).
std::vector<std::string> engine_names();
/// The key, or nullptr when unknown.
const EngineKey* find_engine_key(const std::string& engine, const std::string& key);
/// The case's value for `engine`.`key`, or the default.
double engine_setting(const Scene& scene, const std::string& engine, const std::string& key);
/// Every key of `engine` with the value this case gives it, for a run's engine_settings.
Settings engine_key_settings(const Scene& scene, const std::string& engine);

}  // namespace bb
