// Which backends exist: the reference, the course variants a case asks for, and the
// engine plugins found next to the program.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "reference/gsl_reference.hpp"
#include "scene/backend.hpp"

namespace bb {

class Registry {
 public:
  /// Loads every engine plugin from the plugin folder (see plugin_folder()).
  static Registry load();
  Registry(Registry&&) noexcept;
  Registry& operator=(Registry&&) noexcept;
  ~Registry();

  /// Engines whose plugin loaded, in engine_backend_names() order.
  std::vector<const Backend*> engines() const;
  /// Engine names whose plugin is missing, with why.
  const std::vector<std::pair<std::string, std::string>>& missing_engines() const {
    return missing_;
  }
  const ReferenceBackend& reference() const { return reference_; }
  /// Add a backend that is not a plugin (tests register fakes this way).
  void add_engine(std::unique_ptr<Backend> backend);

 private:
  Registry() = default;
  struct Plugin;
  std::vector<std::unique_ptr<Plugin>> plugins_;
  std::vector<std::unique_ptr<Backend>> engines_;
  std::vector<std::pair<std::string, std::string>> missing_;
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

}  // namespace bb
