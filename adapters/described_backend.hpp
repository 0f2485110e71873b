// A built-in engine's backends as the SDK's DeclaredBackend (seam/declared_backend.hpp), the
// way a plugin built outside the tree makes its own: what each declares is read from the
// engine's description (adapters/<engine>/<engine>_engine.hpp), so the two cannot disagree.
// One plugin gives all of an engine's variants, each chosen at run time by how it starts.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "seam/declared_backend.hpp"
#include "seam/engine_catalogue.hpp"

namespace bb {

/// How an engine variant builds the case's springs: as the engine's own joints, or as forces
/// the adapter adds before each step (the `<engine>/force` backends).
enum class SpringsAs { Joints, Forces };

/// Backend `name` of `engine`, its features and needs as the description gives them.
inline BackendDeclaration described_backend(const EngineDescription& engine,
                                            const std::string& name,
                                            std::pair<std::string, std::string> library_version) {
  const EngineVariant* variant = find_variant(engine, name);
  return {name, variant ? variant->supports : FeatureSet{}, variant ? variant->needs : FeatureSet{},
          std::move(library_version)};
}

/// Starts a `Sim(world, the case's engine tables, dt, options...)`, as every engine's
/// simulation is made; `options` are what tell the engine's variants apart.
template <class Sim, class... Options>
DeclaredBackend::Start start_engine(Options... options) {
  return [=](const World& world, const BackendSettings& settings, double dt) {
    return std::unique_ptr<Simulation>(
        std::make_unique<Sim>(world, *settings.engines, dt, options...));
  };
}

/// One backend a plugin gives: its name in the engine's description and how it starts.
struct VariantStart {
  std::string name;
  DeclaredBackend::Start start;
};

/// A plugin's entry point (BEACHBALL_PLUGIN_BACKENDS): backend number `index` of `starts`, as
/// `engine` describes it, of library `library_version`; nullptr past the last.
inline Backend* engine_backend(const EngineDescription& engine,
                               const std::pair<std::string, std::string>& library_version,
                               const std::vector<VariantStart>& starts, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= starts.size()) return nullptr;
  const VariantStart& variant = starts[static_cast<std::size_t>(index)];
  return new DeclaredBackend(described_backend(engine, variant.name, library_version),
                             variant.start);
}

}  // namespace bb
