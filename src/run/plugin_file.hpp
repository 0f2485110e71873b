// Opening one plugin file and checking it is a backend plugin of this beachball: a shared
// object, built against this plugin interface (scene/plugin_api.hpp), with its entry point.
// Nothing of the plugin is created before the version is checked.
#pragma once

#include <string>
#include <variant>

#include "scene/backend.hpp"

namespace bb {

/// A plugin file opened and found fit to create its backend.
struct OpenedPlugin {
  void* handle = nullptr;
  Backend* (*create)() = nullptr;
};

/// Opens `path` (never closed: engine libraries keep global state that does not survive
/// dlclose) and checks it; the reason it cannot be used otherwise ("was built against
/// beachball plugin interface 2, this beachball has 3: rebuild it").
std::variant<OpenedPlugin, std::string> open_plugin(const std::string& path);

}  // namespace bb
