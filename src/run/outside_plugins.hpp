// Backend plugins built outside beachball's tree, against its SDK: the files named with
// `--plugin PATH.so` and every beachball-*.so in the folders of $BEACHBALL_PLUGIN_PATH. Each
// is opened and checked before any work (a missing file, not a plugin, another interface
// version, a name another backend has: refused, exit 2); each of its backends then joins the
// engine catalogue as an engine of one backend, so that cases, rows, gates and caches treat it
// as a built-in.
#pragma once

#include <string>
#include <vector>

#include "seam/backend.hpp"
#include "seam/engine_catalogue.hpp"

namespace bb {

/// One backend of a plugin from outside the tree, opened and checked (a plugin of several
/// backends is one of these for each).
struct OutsidePlugin {
  std::string path;  ///< as given (or found in the search path)
  std::string real;  ///< its real path: what the build's identity reads
  Backend* (*create)(int index) = nullptr;
  int index = 0;                  ///< the backend's number in its plugin: create(index) makes it
  EngineDescription description;  ///< one backend: its name, features and needs
  std::pair<std::string, std::string> library_version;
};

/// The environment variable of folders searched for beachball-*.so, ':'-separated.
inline constexpr const char* kPluginPathVariable = "BEACHBALL_PLUGIN_PATH";

/// Opens and checks every file of `given` (--plugin), then every beachball-*.so in the folders
/// of $BEACHBALL_PLUGIN_PATH (in name order); throws CaseError(file, 0, reason) for the first
/// that cannot be used. Called once, before any case is loaded.
void load_outside_plugins(const std::vector<std::string>& given);

/// The plugins load_outside_plugins() loaded, in its order.
const std::vector<OutsidePlugin>& outside_plugins();

/// The plugin of backend `name`, or nullptr for a backend that is not one.
const OutsidePlugin* outside_plugin(const std::string& name);

}  // namespace bb
