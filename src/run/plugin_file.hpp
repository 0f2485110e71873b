// Opening one plugin file and checking it is a backend plugin of this beachball: a shared
// object, built against this plugin interface (seam/plugin_api.hpp), with its entry point.
// Nothing of the plugin is created before the version is checked.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "seam/backend.hpp"

namespace bb {

/// A plugin file opened and found fit to create its backends.
struct OpenedPlugin {
  void* handle = nullptr;
  /// Backend number `index` of the plugin (a new object), or nullptr past its last.
  Backend* (*create)(int index) = nullptr;
};

/// Opens `path` (never closed: engine libraries keep global state that does not survive
/// dlclose) and checks it; the reason it cannot be used otherwise ("was built against
/// beachball plugin interface 2, this beachball has 3: rebuild it").
std::variant<OpenedPlugin, std::string> open_plugin(const std::string& path);

/// The most backends one plugin may give: a plugin that never answers nullptr stops here.
inline constexpr int kMostBackendsPerPlugin = 64;

/// Every backend `plugin` gives, in its order.
std::vector<std::unique_ptr<Backend>> plugin_backends(const OpenedPlugin& plugin);

}  // namespace bb
