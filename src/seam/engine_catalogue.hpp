// What each engine adapter says about itself, whether or not its plugin was built: its
// settings table, the backend names it provides and the keys it takes, with defaults. Each
// adapter folder holds its own description (adapters/<engine>/<engine>_engine.hpp); the
// adapters' CMake list gathers them into the catalogue (run/engine_catalogue.hpp), which is
// handed to the loader: the model compiles no adapter's code, and adding an engine touches
// its own folder and that list, nothing in src/.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/features.hpp"

namespace bb {

enum class KeyKind { Number, Integer, Boolean };

struct EngineKey {
  std::string engine;  ///< the [engines.<engine>] table it belongs to
  std::string key;
  KeyKind kind;
  double fallback;      ///< the default; booleans are 0 or 1
  std::string meaning;  ///< one line, with the unit
};

/// One backend of an engine: the engine run one way (its springs as joints or as forces, its
/// precision, its integrator). The engine's plugin chooses the way at run time.
struct EngineVariant {
  std::string name;    ///< the backend's name: "bullet/force"
  std::string colour;  ///< its line on every plot, "#8a564b" ("": one by its name's hash)
  /// The features it can simulate (Backend::supports of its plugin, which returns this), known
  /// here so that a case naming a backend that cannot run it is refused at load, built or not.
  FeatureSet supports;
  /// The features a scene must use for it to take part (Backend::needs); usually none.
  FeatureSet needs = {};
  /// Whether it computes in single precision (tests expect its rounding from here).
  bool single_precision = false;
  /// Why its step has stages (an engine's own RK4) and so does not step like semi-implicit
  /// Euler: what the adapter applies before a step (the force stage, a torque that cancels a
  /// term) is held over the stages while the engine's own forces are not; "" for none.
  std::string staged_step = "";
  /// The plugin file that gives it, beachball-<plugin>.so; "" for the engine's own
  /// (beachball-<engine>.so). A build against another library whose symbols clash with the
  /// engine's (bullet-float) is a plugin of its own.
  std::string plugin = "";
};

struct EngineDescription {
  std::string engine;                   ///< the settings table: [engines.<engine>]
  std::vector<EngineVariant> variants;  ///< its backends, in the order they are listed
  std::vector<EngineKey> keys = {};
  /// False for an engine with no adapter yet: it has a row only when asked for by name.
  bool has_adapter = true;
  /// What the engine does differently, declared here so that tests expect it from the
  /// description, never from the engine's name:
  /// the friction limit is a pyramid (a row per tangent axis: a diagonal slide meets
  /// sqrt(2) mu N) rather than a circle (one row along the slide);
  bool friction_pyramid = false;
  /// per engine_settings key, words its text always holds (the engine's own API, named);
  std::map<std::string, std::string> names_in_settings = {};
  /// the number settings a scene with a hinge reports (a soft joint's ERP and CFM).
  std::vector<std::string> hinge_numbers = {};
};

/// The backend names of `engine`, in its order.
std::vector<std::string> variant_names(const EngineDescription& engine);

/// Backend `name` of `engine`, or nullptr for a name it does not provide.
const EngineVariant* find_variant(const EngineDescription& engine, const std::string& name);

/// The plugin that gives `variant` of `engine`: its own name, or the engine's.
std::string variant_plugin(const EngineDescription& engine, const EngineVariant& variant);

/// Every engine the adapters describe, in the adapters' CMake order.
using EngineCatalogue = std::vector<EngineDescription>;

/// What backend `name` of `engine` supports (none for a name it does not provide).
FeatureSet description_supports(const EngineDescription& engine, const std::string& name);

/// What backend `name` of `catalogue` supports (none for a name it does not know).
FeatureSet catalogue_supports(const EngineCatalogue& catalogue, const std::string& name);

}  // namespace bb
