#include "seam/engine_keys.hpp"

#include <stdexcept>

namespace bb {

const EngineKey* find_engine_key(const EngineDescription& engine, const std::string& key) {
  for (const EngineKey& k : engine.keys)
    if (k.key == key) return &k;
  return nullptr;
}

double engine_setting(const EngineTables& tables, const EngineDescription& engine,
                      const std::string& key) {
  const EngineKey* known = find_engine_key(engine, key);
  if (known == nullptr) throw std::logic_error("no engine setting " + engine.engine + "." + key);
  const auto e = tables.find(engine.engine);
  if (e != tables.end()) {
    const auto v = e->second.find(key);
    if (v != e->second.end()) return v->second.value;
  }
  return known->fallback;
}

Settings engine_key_settings(const EngineTables& tables, const EngineDescription& engine) {
  Settings out;
  for (const EngineKey& k : engine.keys) {
    const double v = engine_setting(tables, engine, k.key);
    if (k.kind == KeyKind::Boolean)
      out.push_back({k.key, v != 0.0});
    else
      out.push_back({k.key, v});
  }
  return out;
}

}  // namespace bb
