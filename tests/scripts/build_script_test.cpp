// scripts/build configures again whenever what the last configure saw has changed: other
// options (BEACHBALL_CMAKE_ARGS, another preset), the presets file edited, a package installed
// since (libpng-dev for the tests, after scripts/report configured without it), a folder of
// another generator.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "support/script_sandbox.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

TEST(BuildScript, ConfiguresOnceThenAgainWhenTheOptionsChange) {
  const test::ScriptSandbox box("build_script_options");
  ASSERT_EQ(box.run("scripts/build", "BEACHBALL_CMAKE_ARGS=-DX=1").exit_code, 0);
  ASSERT_EQ(box.run("scripts/build", "BEACHBALL_CMAKE_ARGS=-DX=1").exit_code, 0);
  EXPECT_EQ(box.configures().size(), 1u) << "the same options twice configure once";
  const test::Outcome changed = box.run("scripts/build", "BEACHBALL_CMAKE_ARGS=-DX=2");
  ASSERT_EQ(changed.exit_code, 0) << changed.out;
  ASSERT_EQ(box.configures().size(), 2u) << changed.out;
  EXPECT_NE(box.configures().back().find("-DX=2"), std::string::npos) << box.configures().back();
  // Every run builds, with the preset the configure used.
  int builds = 0;
  for (const std::string& call : box.calls()) builds += call == "cmake --build --preset default";
  EXPECT_EQ(builds, 3);
}

/// Builds twice with `file` (in the sandbox) older than both, then once after `file` is
/// touched past the last configure: the third configures again, saying `reason`.
void expect_configure_when_newer(const test::ScriptSandbox& box, const std::string& file,
                                 const std::string& reason) {
  const auto now = fs::file_time_type::clock::now();
  // Every file the script watches is older than the configures, but `file` changes later.
  for (const char* watched : {"dpkg-status", "CMakePresets.json"})
    if (fs::exists(box.root() + "/" + watched))
      fs::last_write_time(box.root() + "/" + watched, now - std::chrono::seconds(120));
  ASSERT_EQ(box.run("scripts/build").exit_code, 0);
  ASSERT_EQ(box.run("scripts/build").exit_code, 0);
  EXPECT_EQ(box.configures().size(), 1u);
  // The last configure a minute ago; the file changed since.
  fs::last_write_time(box.root() + "/build/beachball-configure.txt",
                      now - std::chrono::seconds(60));
  fs::last_write_time(box.root() + "/" + file, now - std::chrono::seconds(30));
  const test::Outcome after = box.run("scripts/build");
  ASSERT_EQ(after.exit_code, 0) << after.out;
  EXPECT_EQ(box.configures().size(), 2u) << after.out;
  EXPECT_NE(after.out.find(reason), std::string::npos) << after.out;
}

TEST(BuildScript, ConfiguresAgainWhenAPackageWasInstalledSince) {
  const test::ScriptSandbox box("build_script_packages");
  expect_configure_when_newer(box, "dpkg-status", "packages changed");
}

TEST(BuildScript, ConfiguresAgainWhenThePresetsChanged) {
  const test::ScriptSandbox box("build_script_presets");
  std::ofstream(box.root() + "/CMakePresets.json") << "{}\n";
  expect_configure_when_newer(box, "CMakePresets.json", "CMakePresets.json changed");
}

TEST(BuildScript, AFolderMadeWithMakefilesIsConfiguredForNinja) {
  const test::ScriptSandbox box("build_script_generator");
  ASSERT_EQ(box.run("scripts/build").exit_code, 0);
  std::ofstream(box.root() + "/build/CMakeCache.txt")
      << "CMAKE_GENERATOR:INTERNAL=Unix Makefiles\n";
  fs::create_directories(box.root() + "/build/CMakeFiles");
  const test::Outcome after = box.run("scripts/build");
  ASSERT_EQ(after.exit_code, 0) << after.out;
  EXPECT_EQ(box.configures().size(), 2u) << after.out;
  EXPECT_FALSE(fs::exists(box.root() + "/build/CMakeFiles"));
}

TEST(BuildScript, BuildsTheTargetsItIsGiven) {
  const test::ScriptSandbox box("build_script_targets");
  ASSERT_EQ(box.run("scripts/build program").exit_code, 0);
  EXPECT_EQ(box.calls().back(), "cmake --build --preset default --target program");
}

}  // namespace
}  // namespace bb
