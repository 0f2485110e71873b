#include "run/registry.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "course/course_backend.hpp"
#include "run/engine_catalogue.hpp"
#include "run/outside_plugins.hpp"
#include "run/plugin_file.hpp"
#include "scene/backend_names.hpp"
#include "scene/engine_catalogue.hpp"

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

std::string plugin_file_name(const std::string& backend) {
  std::string file = "beachball-" + backend + ".so";
  std::replace(file.begin(), file.end(), '/', '-');
  return file;
}

Registry Registry::load() {
  Registry r;
  const std::filesystem::path folder = plugin_folder();
  for (const EngineDescription& engine : built_in_engine_catalogue())
    for (const EngineVariant& variant : engine.variants) r.load_plugin(folder, variant, engine);
  // The plugins from outside the tree, checked when they were opened (outside_plugins.hpp).
  for (const OutsidePlugin& plugin : outside_plugins())
    r.engines_.emplace_back(plugin.create(plugin.index));
  return r;
}

void Registry::load_plugin(const std::filesystem::path& folder, const EngineVariant& variant,
                           const EngineDescription& engine) {
  const std::string& name = variant.name;
  if (!engine.has_adapter) {
    missing_.push_back({name, "no adapter in this version of beachball", false});
    return;
  }
  const FeatureSet& needs = variant.needs;
  const std::filesystem::path path = folder / plugin_file_name(name);
  if (!std::filesystem::exists(path)) {
    missing_.push_back(
        {name, "not built: its Debian package was not found at build time", true, needs});
    return;
  }
  auto opened = open_plugin(path.string());
  if (const auto* why = std::get_if<std::string>(&opened)) {
    missing_.push_back({name, "plugin " + *why, true, needs});
    return;
  }
  engines_.emplace_back(std::get<OpenedPlugin>(opened).create(0));
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
