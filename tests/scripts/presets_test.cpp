// The CMake presets: warnings are errors in CI's build and the developers' preset, never in
// the default a user builds (another compiler's new warning must not stop their build), and
// every preset uses Ninja.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using nlohmann::json;

json presets() {
  std::ifstream in(test::source_path("CMakePresets.json"));
  return json::parse(in);
}

/// A configure preset's cache variables and generator, its parents' included.
json resolved(const json& all, const std::string& name) {
  for (const json& p : all["configurePresets"]) {
    if (p["name"] != name) continue;
    json out = p.contains("inherits") ? resolved(all, p["inherits"]) : json::object();
    if (p.contains("generator")) out["generator"] = p["generator"];
    for (const auto& [key, value] : p.value("cacheVariables", json::object()).items())
      out["cacheVariables"][key] = value;
    return out;
  }
  ADD_FAILURE() << "no configure preset " << name;
  return json::object();
}

bool warnings_are_errors(const json& preset) {
  const json vars = preset.value("cacheVariables", json::object());
  return vars.value("BEACHBALL_WERROR", "OFF") == "ON" ||
         vars.value("CMAKE_CXX_FLAGS", "").find("-Werror") != std::string::npos;
}

TEST(Presets, WarningsAreErrorsInCiAndTheDevPresetNotInTheDefault) {
  const json all = presets();
  EXPECT_FALSE(warnings_are_errors(resolved(all, "default")));
  EXPECT_TRUE(warnings_are_errors(resolved(all, "dev")));
  EXPECT_TRUE(warnings_are_errors(resolved(all, "asan")));
  // CI builds the asan preset.
  const std::string ci = test::bytes(test::source_path(".ci/run"));
  EXPECT_NE(ci.find("BEACHBALL_PRESET=asan"), std::string::npos);
  // -Werror only where BEACHBALL_WERROR asks for it, and the option is off by default.
  const std::string cmake = test::bytes(test::source_path("CMakeLists.txt"));
  EXPECT_EQ(cmake.find("-Wextra -Werror"), std::string::npos);
  EXPECT_NE(cmake.find("$<$<BOOL:${BEACHBALL_WERROR}>:-Werror>"), std::string::npos);
  const std::size_t option = cmake.find("option(BEACHBALL_WERROR");
  ASSERT_NE(option, std::string::npos);
  EXPECT_EQ(cmake.substr(cmake.find(')', option) - 3, 3), "OFF");
}

TEST(Presets, EveryPresetUsesNinja) {
  const json all = presets();
  for (const json& p : all["configurePresets"])
    EXPECT_EQ(resolved(all, p["name"]).value("generator", ""), "Ninja") << p["name"];
}

}  // namespace
}  // namespace bb
