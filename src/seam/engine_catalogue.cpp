#include "seam/engine_catalogue.hpp"

#include <algorithm>

namespace bb {

std::vector<std::string> variant_names(const EngineDescription& engine) {
  std::vector<std::string> out;
  for (const EngineVariant& v : engine.variants) out.push_back(v.name);
  return out;
}

const EngineVariant* find_variant(const EngineDescription& engine, const std::string& name) {
  const auto found = std::find_if(engine.variants.begin(), engine.variants.end(),
                                  [&](const EngineVariant& v) { return v.name == name; });
  return found == engine.variants.end() ? nullptr : &*found;
}

std::string variant_plugin(const EngineDescription& engine, const EngineVariant& variant) {
  return variant.plugin.empty() ? engine.engine : variant.plugin;
}

FeatureSet description_supports(const EngineDescription& engine, const std::string& name) {
  const EngineVariant* variant = find_variant(engine, name);
  return variant == nullptr ? FeatureSet{} : variant->supports;
}

FeatureSet catalogue_supports(const EngineCatalogue& catalogue, const std::string& name) {
  for (const EngineDescription& e : catalogue)
    if (find_variant(e, name) != nullptr) return description_supports(e, name);
  return {};
}

}  // namespace bb
