// The backend class every plugin would otherwise write again: what it declares about itself
// (name, features, needs, library and version) held once, and how it starts a run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "seam/backend.hpp"

namespace bb {

/// What a backend says about itself: `beachball list` shows it, the runner trusts it.
struct BackendDeclaration {
  /// The row's name: "mine/symplectic-euler". Unique among every backend of the program.
  std::string name;
  /// The features it simulates; a scene using one more is a row `unsupported`.
  FeatureSet supports;
  /// Features a scene must use for it to take part at all (Backend::needs); usually none.
  FeatureSet needs = {};
  /// Library and version, e.g. {"mine", "1.2"}; empty name for none.
  std::pair<std::string, std::string> library_version = {};
};

/// A backend whose runs `start` begins: (world, settings, dt) -> a new Simulation.
class DeclaredBackend final : public Backend {
 public:
  using Start =
      std::function<std::unique_ptr<Simulation>(const World&, const BackendSettings&, double)>;
  DeclaredBackend(BackendDeclaration declaration, Start start)
      : declaration_(std::move(declaration)), start_(std::move(start)) {}

  std::string name() const override { return declaration_.name; }
  FeatureSet supports() const override { return declaration_.supports; }
  FeatureSet needs() const override { return declaration_.needs; }
  std::pair<std::string, std::string> library_version() const override {
    return declaration_.library_version;
  }
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                        double dt) const override {
    return start_(world, settings, dt);
  }

  /// A backend whose simulation is `Sim(world, settings, dt)`.
  template <class Sim>
  static DeclaredBackend* of(BackendDeclaration declaration) {
    return new DeclaredBackend(std::move(declaration),
                               [](const World& world, const BackendSettings& settings, double dt) {
                                 return std::make_unique<Sim>(world, settings, dt);
                               });
  }

 private:
  BackendDeclaration declaration_;
  Start start_;
};

}  // namespace bb
