// Which backends exist: the reference, the course variants a case asks for, and the
// engine plugins found next to the program.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "reference/gsl_reference.hpp"
#include "seam/backend.hpp"
#include "seam/engine_catalogue.hpp"

namespace bb {

class Registry {
 public:
  /// Loads every engine plugin from the plugin folder (see plugin_folder()), then creates the
  /// backends of the plugins from outside the tree (outside_plugins.hpp).
  static Registry load();
  Registry(Registry&&) noexcept;
  Registry& operator=(Registry&&) noexcept;
  ~Registry();

  /// Engine backends whose plugin loaded, in engine_backend_names() order, then the plugins
  /// from outside the tree.
  std::vector<const Backend*> engines() const;
  /// An engine backend whose plugin is not here.
  struct Missing {
    std::string name;
    std::string why;
    bool shown_unasked = true;  ///< false for an engine with no adapter yet
    FeatureSet needs = {};      ///< shown only on scenes that use these
  };
  /// Engine backends whose plugin is missing, with why.
  const std::vector<Missing>& missing_engines() const { return missing_; }
  const ReferenceBackend& reference() const { return reference_; }
  /// What every course variant supports (they differ in rules, not in features).
  FeatureSet course_features() const;
  /// Add a backend that is not a plugin (tests register fakes this way).
  void add_engine(std::unique_ptr<Backend> backend);

 private:
  Registry() = default;
  /// Loads the backends of `engine` from its plugins in `folder`, in the description's order,
  /// and records why each one that is not there is missing.
  void load_engine(const std::filesystem::path& folder, const EngineDescription& engine);
  std::vector<std::unique_ptr<Backend>> engines_;
  std::vector<Missing> missing_;
  ReferenceBackend reference_;
};

/// The backends a case runs, the course variants owned here: reference first, then the
/// course variants, then the engines.
struct BackendSet {
  std::vector<std::unique_ptr<Backend>> owned;
  std::vector<const Backend*> all;  ///< excludes the reference
};
BackendSet backends_for(const Scene& scene, const Registry& registry);

/// Where engine plugins are looked for: $BEACHBALL_PLUGIN_DIR, else plugins/ next to the program.
std::string plugin_folder();

/// The file of plugin `plugin`: beachball-<plugin>.so, a slash in the name written as a dash.
std::string plugin_file_name(const std::string& plugin);

/// The plugin file that gives backend `backend`: its engine's plugin (one for all of an
/// engine's variants, or the one its description names: bullet-float's), or, for a name no
/// engine describes, plugin_file_name(backend).
std::string backend_plugin_file(const std::string& backend);

}  // namespace bb
