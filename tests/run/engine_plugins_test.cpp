// One plugin per engine: each engine's backends come from its own plugin file
// (beachball-<engine>.so), which gives every backend of its description but those the
// description puts in a plugin of their own (bullet-float, whose library clashes with
// bullet's), in the description's order, and no file is built per backend.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "run/engine_catalogue.hpp"
#include "run/plugin_file.hpp"
#include "run/registry.hpp"
#include "support/engine_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Per plugin file of `engine`, the backends its description puts in it, in its order.
std::map<std::string, std::vector<std::string>> described_plugins(const EngineDescription& engine) {
  std::map<std::string, std::vector<std::string>> out;
  for (const EngineVariant& v : engine.variants)
    out[plugin_file_name(variant_plugin(engine, v))].push_back(v.name);
  return out;
}

TEST(EnginePlugins, EachPluginGivesTheBackendsItsDescriptionPutsInIt) {
  std::vector<std::string> not_built;
  for (const EngineDescription& engine : built_in_engine_catalogue()) {
    if (!engine.has_adapter) continue;
    for (const auto& [file, names] : described_plugins(engine)) {
      const fs::path path = fs::path(plugin_folder()) / file;
      if (!fs::exists(path)) {
        not_built.insert(not_built.end(), names.begin(), names.end());
        continue;
      }
      auto opened = open_plugin(path.string());
      ASSERT_TRUE(std::holds_alternative<OpenedPlugin>(opened)) << std::get<std::string>(opened);
      std::vector<std::string> given;
      for (const auto& backend : plugin_backends(std::get<OpenedPlugin>(opened)))
        given.push_back(backend->name());
      EXPECT_EQ(given, names) << file;
      for (const std::string& name : names) EXPECT_EQ(backend_plugin_file(name), file) << name;
    }
  }
  BB_SKIP_IF_MISSING(test::not_built(not_built));
}

TEST(EnginePlugins, NoFileIsBuiltPerBackend) {
  for (const EngineDescription& engine : built_in_engine_catalogue()) {
    const auto plugins = described_plugins(engine);
    for (const EngineVariant& v : engine.variants) {
      const std::string own = plugin_file_name(v.name);
      if (plugins.count(own) == 0) {
        EXPECT_FALSE(fs::exists(fs::path(plugin_folder()) / own)) << own << " is built apart";
      }
    }
  }
}

}  // namespace
}  // namespace bb
