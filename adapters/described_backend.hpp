// A built-in engine's backend as the SDK's DeclaredBackend (scene/declared_backend.hpp), the
// way a plugin built outside the tree makes its own: what it declares is read from the
// engine's description (adapters/<engine>/<engine>_engine.hpp), so the two cannot disagree.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "scene/declared_backend.hpp"
#include "scene/engine_catalogue.hpp"

namespace bb {

/// Backend `name` of `engine`, its features and needs as the description gives them.
inline BackendDeclaration described_backend(const EngineDescription& engine,
                                            const std::string& name,
                                            std::pair<std::string, std::string> library_version) {
  const EngineVariant* variant = find_variant(engine, name);
  return {name, variant ? variant->supports : FeatureSet{}, variant ? variant->needs : FeatureSet{},
          std::move(library_version)};
}

/// Starts a `Sim(world, the case's engine tables, dt)`, as every engine's simulation is made.
template <class Sim>
std::unique_ptr<Simulation> start_engine(const World& world, const BackendSettings& settings,
                                         double dt) {
  return std::make_unique<Sim>(world, *settings.engines, dt);
}

}  // namespace bb
