#include "run/plugin_file.hpp"

#include <dlfcn.h>

#include "seam/plugin_api.hpp"

namespace bb {

std::variant<OpenedPlugin, std::string> open_plugin(const std::string& path) {
  // RTLD_LOCAL keeps each plugin's engine symbols apart: bullet and bullet-float link
  // libraries that define the same names with different layouts.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    return std::string("failed to load: ") + (why ? why : "dlopen gave no reason");
  }
  // The version first: a plugin of another interface must not create anything here.
  auto version = reinterpret_cast<int (*)()>(dlsym(handle, BEACHBALL_PLUGIN_VERSION_ENTRY));
  if (version == nullptr)
    return std::string("has no " BEACHBALL_PLUGIN_VERSION_ENTRY
                       " (it was not built with the SDK's BEACHBALL_PLUGIN, or before "
                       "beachball plugin interface " +
                       std::to_string(BEACHBALL_PLUGIN_INTERFACE_VERSION) +
                       "): rebuild it against this beachball");
  if (const int theirs = version(); theirs != BEACHBALL_PLUGIN_INTERFACE_VERSION)
    return "was built against beachball plugin interface " + std::to_string(theirs) +
           ", this beachball has " + std::to_string(BEACHBALL_PLUGIN_INTERFACE_VERSION) +
           ": rebuild it";
  auto create = reinterpret_cast<Backend* (*)(int)>(dlsym(handle, BEACHBALL_PLUGIN_ENTRY));
  if (create == nullptr) return std::string("has no " BEACHBALL_PLUGIN_ENTRY);
  return OpenedPlugin{handle, create};
}

std::vector<std::unique_ptr<Backend>> plugin_backends(const OpenedPlugin& plugin) {
  std::vector<std::unique_ptr<Backend>> out;
  for (int index = 0; index < kMostBackendsPerPlugin; ++index) {
    std::unique_ptr<Backend> backend(plugin.create(index));
    if (!backend) break;
    out.push_back(std::move(backend));
  }
  return out;
}

}  // namespace bb
