// An engine plugin links the model with the seam (libbb_model.so) and the force model, never
// the study: no plugin loads the case loader's TOML library (docs/architecture.md). Read from
// each built plugin's libraries as the dynamic linker resolves them (ldd), so a library the
// model pulls in counts too.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/missing.hpp"
#include "support/program.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Every engine plugin the build put next to the program (beachball-<plugin>.so).
std::vector<fs::path> engine_plugins() {
  const fs::path folder = fs::path(BEACHBALL_PROGRAM).parent_path() / "plugins";
  std::vector<fs::path> out;
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("beachball-", 0) == 0 && entry.path().extension() == ".so")
        out.push_back(entry.path());
    }
  return out;
}

TEST(PluginLinks, EveryEnginePluginLoadsTheModelAndNeitherTheStudyNorTheTomlLibrary) {
  const std::vector<fs::path> plugins = engine_plugins();
  BB_SKIP_IF_MISSING(plugins.empty() ? std::string("no engine plugin was built") : "");
  for (const fs::path& plugin : plugins) {
    const test::Outcome libraries = test::shell("ldd '" + plugin.string() + "'");
    ASSERT_EQ(libraries.exit_code, 0) << plugin << ":\n" << libraries.out;
    // The model is there: what ldd printed is the plugin's libraries, not an empty answer.
    EXPECT_NE(libraries.out.find("libbb_model.so"), std::string::npos) << plugin << ":\n"
                                                                       << libraries.out;
    EXPECT_EQ(libraries.out.find("libbb_study"), std::string::npos)
        << plugin << " links the study:\n"
        << libraries.out;
    EXPECT_EQ(libraries.out.find("toml"), std::string::npos)
        << plugin << " loads the TOML library:\n"
        << libraries.out;
  }
}

}  // namespace
}  // namespace bb
