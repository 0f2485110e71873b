#include "scene/engine_keys.hpp"

#include <stdexcept>

namespace bb {

std::vector<std::string> engine_names() {
  std::vector<std::string> out;
  for (const EngineDescription& e : engine_catalogue()) out.push_back(e.engine);
  return out;
}

const EngineKey* find_engine_key(const std::string& engine, const std::string& key) {
  for (const EngineDescription& e : engine_catalogue())
    for (const EngineKey& k : e.keys)
      if (k.engine == engine && k.key == key) return &k;
  return nullptr;
}

double engine_setting(const EngineTables& tables, const std::string& engine,
                      const std::string& key) {
  const EngineKey* known = find_engine_key(engine, key);
  if (known == nullptr) throw std::logic_error("no engine setting " + engine + "." + key);
  const auto e = tables.find(engine);
  if (e != tables.end()) {
    const auto v = e->second.find(key);
    if (v != e->second.end()) return v->second.value;
  }
  return known->fallback;
}

Settings engine_key_settings(const EngineTables& tables, const std::string& engine) {
  Settings out;
  for (const EngineDescription& e : engine_catalogue()) {
    if (e.engine != engine) continue;
    for (const EngineKey& k : e.keys) {
      const double v = engine_setting(tables, engine, k.key);
      if (k.kind == KeyKind::Boolean)
        out.push_back({k.key, v != 0.0});
      else
        out.push_back({k.key, v});
    }
  }
  return out;
}

}  // namespace bb
