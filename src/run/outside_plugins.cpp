#include "run/outside_plugins.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "run/engine_catalogue.hpp"
#include "run/plugin_file.hpp"
#include "seam/plugin_api.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace fs = std::filesystem;

namespace {

std::vector<OutsidePlugin>& loaded() {
  static std::vector<OutsidePlugin> plugins;
  return plugins;
}

/// Why `name` cannot be a plugin's backend name, or "".
std::string name_problem(const std::string& name) {
  if (name.empty()) return "its backend has an empty name";
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.' || c == '/' || c == '+';
  });
  if (!plain || name.front() == '/' || name.size() > 64)
    return "its backend's name '" + name +
           "' is not 1 to 64 letters, digits and - _ . / + (not starting with /)";
  // The reference, the course's variants and imported trajectories name their own rows.
  for (const char* own : {kReferenceName, "course", "import"})
    if (name == own || name.rfind(std::string(own) + "/", 0) == 0 ||
        name.rfind(std::string(own) + "+", 0) == 0)
      return "its backend's name '" + name + "' is one of beachball's own (" + own +
             "...): give it another name";
  for (const std::string& built_in : engine_backend_names(built_in_engine_catalogue()))
    if (name == built_in)
      return "its backend's name '" + name + "' is a built-in backend's name: give it another name";
  for (const OutsidePlugin& p : loaded())
    if (p.description.variants.front().name == name)
      return "its backend's name '" + name + "' is the name of the backend of " + p.path +
             ": give one of them another name";
  return "";
}

/// Opens `path`, checks it and adds it; throws CaseError with the reason it cannot be.
void load_one(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw CaseError(path, 0, "no such plugin file");
  const std::string real = fs::canonical(path, ec).string();
  for (const OutsidePlugin& p : loaded())
    if (p.real == real) return;  // named twice (--plugin and the search path): once
  auto opened = open_plugin(real);
  if (const auto* why = std::get_if<std::string>(&opened)) throw CaseError(path, 0, *why);
  const OpenedPlugin plugin = std::get<OpenedPlugin>(opened);
  const std::vector<std::unique_ptr<Backend>> backends = plugin_backends(plugin);
  if (backends.empty())
    throw CaseError(path, 0, "its " BEACHBALL_PLUGIN_ENTRY " returned no backend");
  for (std::size_t index = 0; index < backends.size(); ++index) {
    const Backend& backend = *backends[index];
    const std::string name = backend.name();
    if (const std::string problem = name_problem(name); !problem.empty())
      throw CaseError(path, 0, problem);
    const EngineDescription description{.engine = name,
                                        // No colour of its own: the report picks one by its name.
                                        .variants = {{.name = name,
                                                      .colour = "",
                                                      .supports = backend.supports(),
                                                      .needs = backend.needs()}}};
    loaded().push_back({path, real, plugin.create, static_cast<int>(index), description,
                        backend.library_version()});
  }
}

/// Every beachball-*.so in the folders of $BEACHBALL_PLUGIN_PATH, each folder in name order.
std::vector<std::string> search_path_files() {
  std::vector<std::string> out;
  const char* env = std::getenv(kPluginPathVariable);
  std::string rest = env ? env : "";
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const std::string folder = rest.substr(0, colon);
    rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
    if (folder.empty()) continue;
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
      throw CaseError(folder, 0,
                      std::string("is in $") + kPluginPathVariable + " but is not a folder");
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      const std::string file = entry.path().filename().string();
      if (file.rfind("beachball-", 0) == 0 && entry.path().extension() == ".so")
        files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    out.insert(out.end(), files.begin(), files.end());
  }
  return out;
}

}  // namespace

void load_outside_plugins(const std::vector<std::string>& given) {
  for (const std::string& path : given) load_one(path);
  for (const std::string& path : search_path_files()) load_one(path);
}

const std::vector<OutsidePlugin>& outside_plugins() {
  return loaded();
}

const EngineCatalogue& engine_catalogue() {
  // Rebuilt when plugins were added since: they are, once, before any case is loaded.
  static EngineCatalogue all;
  const EngineCatalogue& built_in = built_in_engine_catalogue();
  if (all.size() != built_in.size() + loaded().size()) {
    all = built_in;
    for (const OutsidePlugin& p : loaded()) all.push_back(p.description);
  }
  return all;
}

const OutsidePlugin* outside_plugin(const std::string& name) {
  for (const OutsidePlugin& p : loaded())
    if (p.description.variants.front().name == name) return &p;
  return nullptr;
}

}  // namespace bb
