#include "run/registry.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "course/course_backend.hpp"
#include "run/engine_catalogue.hpp"
#include "run/outside_plugins.hpp"
#include "run/plugin_file.hpp"
#include "seam/engine_catalogue.hpp"
#include "study/backend_names.hpp"

namespace bb {

Registry::Registry(Registry&&) noexcept = default;
Registry& Registry::operator=(Registry&&) noexcept = default;
Registry::~Registry() = default;

std::string plugin_folder() {
  if (const char* env = std::getenv("BEACHBALL_PLUGIN_DIR"); env && *env) return env;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("plugins") : (exe.parent_path() / "plugins").string();
}

std::string plugin_file_name(const std::string& plugin) {
  std::string file = "beachball-" + plugin + ".so";
  std::replace(file.begin(), file.end(), '/', '-');
  return file;
}

std::string backend_plugin_file(const std::string& backend) {
  for (const EngineDescription& engine : built_in_engine_catalogue())
    if (const EngineVariant* variant = find_variant(engine, backend))
      return plugin_file_name(variant_plugin(engine, *variant));
  return plugin_file_name(backend);
}

namespace {

/// One engine plugin file, opened: its backends by name, or why it gives none.
struct EnginePlugin {
  std::map<std::string, std::unique_ptr<Backend>> backends;
  std::string why;
};

EnginePlugin open_engine_plugin(const std::filesystem::path& path) {
  EnginePlugin out;
  if (!std::filesystem::exists(path)) {
    out.why = "not built: its Debian package was not found at build time";
    return out;
  }
  auto opened = open_plugin(path.string());
  if (const auto* why = std::get_if<std::string>(&opened)) {
    out.why = "plugin " + *why;
    return out;
  }
  for (std::unique_ptr<Backend>& backend : plugin_backends(std::get<OpenedPlugin>(opened))) {
    const std::string name = backend->name();
    out.backends.emplace(name, std::move(backend));
  }
  return out;
}

}  // namespace

Registry Registry::load() {
  Registry r;
  const std::filesystem::path folder = plugin_folder();
  for (const EngineDescription& engine : built_in_engine_catalogue()) r.load_engine(folder, engine);
  // The plugins from outside the tree, checked when they were opened (outside_plugins.hpp).
  for (const OutsidePlugin& plugin : outside_plugins())
    r.engines_.emplace_back(plugin.create(plugin.index));
  return r;
}

void Registry::load_engine(const std::filesystem::path& folder, const EngineDescription& engine) {
  // Each plugin file is opened once, however many of the engine's backends it gives.
  std::map<std::string, EnginePlugin> plugins;
  for (const EngineVariant& variant : engine.variants) {
    const std::string& name = variant.name;
    if (!engine.has_adapter) {
      missing_.push_back({name, "no adapter in this version of beachball", false});
      continue;
    }
    const std::string file = plugin_file_name(variant_plugin(engine, variant));
    auto [at, first] = plugins.try_emplace(file);
    if (first) at->second = open_engine_plugin(folder / file);
    EnginePlugin& plugin = at->second;
    const auto found = plugin.backends.find(name);
    if (!plugin.why.empty() || found == plugin.backends.end()) {
      const std::string why =
          !plugin.why.empty() ? plugin.why
                              : "plugin " + file + " gives no backend '" + name + "': rebuild it";
      missing_.push_back({name, why, true, variant.needs});
      continue;
    }
    engines_.push_back(std::move(found->second));
  }
}

FeatureSet Registry::course_features() const {
  return CourseBackend(CourseVariant{}).supports();
}

std::vector<const Backend*> Registry::engines() const {
  std::vector<const Backend*> out;
  for (const auto& e : engines_) out.push_back(e.get());
  return out;
}

void Registry::add_engine(std::unique_ptr<Backend> backend) {
  engines_.push_back(std::move(backend));
}

BackendSet backends_for(const Scene& scene, const Registry& registry) {
  BackendSet set;
  for (const CourseVariant& v : course_variants(scene))
    set.owned.push_back(std::make_unique<CourseBackend>(v));
  for (const auto& b : set.owned) set.all.push_back(b.get());
  // An engine variant that differs from its engine only where the scene uses some feature
  // (springs applied by hand) takes part only in scenes that use it.
  for (const Backend* e : registry.engines())
    if (e->needs().missing_from(scene.features()).empty()) set.all.push_back(e);
  return set;
}

}  // namespace bb
