// The bundled suite for the benchmarks: every case file of cases/ loaded, and each case's
// backends that support it, with the engine plugins next to the program.
#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <vector>

#include "run/case_loading.hpp"
#include "run/registry.hpp"

namespace bench {

/// Every case of the bundled suite, in name order.
inline std::vector<bb::Scene> bundled_cases() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(BEACHBALL_CASES_DIR))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<bb::Scene> scenes;
  for (const auto& f : files) scenes.push_back(bb::load_case(f.string()));
  return scenes;
}

/// Calls `each` for every case of the bundled suite with every backend that supports it; the
/// cases and backends live as long as the program.
inline void for_each_supported(
    const std::function<void(const bb::Scene&, const bb::Backend&)>& each) {
  static const std::vector<bb::Scene> scenes = bundled_cases();
  static const bb::Registry registry = bb::Registry::load();
  static std::vector<bb::BackendSet> sets;
  sets.reserve(scenes.size());
  for (const bb::Scene& scene : scenes) {
    sets.push_back(bb::backends_for(scene, registry));
    for (const bb::Backend* backend : sets.back().all)
      if (scene.features().missing_from(backend->supports()).empty()) each(scene, *backend);
  }
}

}  // namespace bench
