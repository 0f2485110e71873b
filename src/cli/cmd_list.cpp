#include <fmt/format.h>

#include "cli/commands.hpp"
#include "run/accuracy_run.hpp"
#include "run/outside_plugins.hpp"
#include "study/backend_names.hpp"

namespace bb::cli {

namespace {

std::string feature_list(const FeatureSet& set) {
  std::string out;
  for (Feature f : all_features())
    if (set.has(f)) out += (out.empty() ? "" : ", ") + feature_name(f);
  return out.empty() ? "-" : out;
}

}  // namespace

int list_command(const std::vector<std::string>& paths) {
  const std::vector<Scene> scenes = load_cases(paths);
  const Registry registry = Registry::load();
  fmt::print("Backends:\n");
  fmt::print("  {:<28} {}\n", kReferenceName, feature_list(registry.reference().supports()));
  fmt::print("  {:<28} {}\n", "course/<integrator>", feature_list(registry.course_features()));
  for (const Backend* e : registry.engines()) {
    const auto [library, version] = e->library_version();
    const OutsidePlugin* outside = outside_plugin(e->name());
    fmt::print("  {:<28} {} ({} {}): {}\n", e->name(),
               outside ? "plugin " + outside->path : std::string("built"), library, version,
               feature_list(e->supports()));
  }
  for (const Registry::Missing& m : registry.missing_engines())
    fmt::print("  {:<28} {}\n", m.name, m.why);
  fmt::print("  course integrators: ");
  for (const std::string& i : known_integrators()) fmt::print("{} ", i);
  fmt::print("\n\nCases:\n");
  for (const Scene& scene : scenes) {
    fmt::print("  {} ({}D) - {}\n    file: {}\n    uses: {}\n", scene.name, scene.dims, scene.title,
               scene.file, feature_list(scene.features()));
    const BackendSet set = backends_for(scene, registry);
    for (const Backend* b : set.all) {
      const std::string missing = missing_features(*b, scene);
      fmt::print("    {:<28} {}\n", b->name(),
                 missing.empty() ? "runs" : "unsupported: " + missing);
    }
  }
  return kExitOk;
}

}  // namespace bb::cli
