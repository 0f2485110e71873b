// The CMake presets: warnings are errors in CI's build and the developers' preset, never in
// the default a user builds (another compiler's new warning must not stop their build), CI's
// test programs at -O0 beside optimised code under test, its quick test folders run as shards,
// and every preset uses Ninja.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "run/child_pool.hpp"
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
  for (const json& p : all.at("configurePresets")) {
    if (p.at("name").get<std::string>() != name) continue;
    json out = json::object();
    if (p.contains("inherits")) out = resolved(all, p.at("inherits").get<std::string>());
    if (p.contains("generator")) out["generator"] = p.at("generator");
    if (p.contains("cacheVariables"))
      for (const auto& [key, value] : p.at("cacheVariables").items())
        out["cacheVariables"][key] = value;
    return out;
  }
  ADD_FAILURE() << "no configure preset " << name;
  return json::object();
}

bool warnings_are_errors(const json& preset) {
  if (!preset.contains("cacheVariables")) return false;
  const json& vars = preset.at("cacheVariables");
  return vars.value("BEACHBALL_WERROR", std::string("OFF")) == "ON" ||
         vars.value("CMAKE_CXX_FLAGS", std::string()).find("-Werror") != std::string::npos;
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
  const std::size_t end = cmake.find(")\n", option);
  EXPECT_EQ(cmake.substr(end - 3, 3), "OFF") << cmake.substr(option, end - option);
}

// CI's build, by clang: the code under test optimised (-O2) under both sanitizers, the test
// programs' own code at -O0 and without them (about half their compile time; it is not the code
// under test, which keeps both sanitizers in the test programs too, as libraries).
TEST(Presets, CiOptimisesTheCodeUnderTestAndCompilesTheTestProgramsAtO0) {
  const json vars = resolved(presets(), "asan").at("cacheVariables");
  const std::string flags = vars.value("CMAKE_CXX_FLAGS", std::string());
  EXPECT_EQ(vars.value("CMAKE_CXX_COMPILER", std::string()), "clang++");
  EXPECT_NE(flags.find("-O2"), std::string::npos) << flags;
  EXPECT_NE(flags.find("-fsanitize=address,undefined"), std::string::npos) << flags;
  EXPECT_EQ(vars.value("BEACHBALL_TEST_COMPILE_OPTIONS", std::string()), "-O0;-fno-sanitize=all");
  // This test program is one of them: built with the asan preset's flags, it is neither
  // optimised nor instrumented, while the library it tests is.
  if (std::string(BEACHBALL_CXX_FLAGS) == flags) {
#ifdef __OPTIMIZE__
    ADD_FAILURE() << "a test program of the asan build was compiled with optimisation";
#endif
#if defined(__SANITIZE_ADDRESS__)
    ADD_FAILURE() << "a test program's own code was compiled with AddressSanitizer";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    ADD_FAILURE() << "a test program's own code was compiled with AddressSanitizer";
#endif
#endif
    EXPECT_FALSE(children_memory_capped()) << "the library under test is not instrumented";
  }
}

// CI's build runs the folders of quick tests as GoogleTest shards, the developers' builds one
// ctest entry per test; in this build, a folder's shards run its program with every shard
// index once, and a sharded folder has no entry of a single test beside them.
TEST(Presets, CiRunsTheQuickFoldersAsShardsThatTogetherRunEveryTest) {
  const json all = presets();
  EXPECT_EQ(resolved(all, "asan").at("cacheVariables").value("BEACHBALL_TEST_SHARDS", ""), "2");
  EXPECT_FALSE(resolved(all, "default").at("cacheVariables").contains("BEACHBALL_TEST_SHARDS"));
  const test::Outcome listed = test::shell("ctest --test-dir " + std::string(BEACHBALL_BUILD_DIR) +
                                           " --show-only=json-v1 2>&1");
  ASSERT_EQ(listed.exit_code, 0) << listed.out;
  std::map<std::string, std::set<int>> shard_indices;  // by program
  std::map<std::string, int> shard_totals;
  std::map<std::string, std::set<std::string>> kinds;  // by label: "shard" or "test"
  const json registered = json::parse(listed.out);
  for (const json& t : registered.at("tests")) {
    const std::string name = t.at("name").get<std::string>();
    std::string label, environment;
    for (const json& property : t.value("properties", json::array())) {
      if (property.at("name") == "LABELS") label = property.at("value").at(0).get<std::string>();
      if (property.at("name") == "ENVIRONMENT")
        for (const json& v : property.at("value")) environment += v.get<std::string>() + ";";
    }
    const std::size_t at = name.find(".shard");
    kinds[label].insert(at == std::string::npos ? "test" : "shard");
    if (at == std::string::npos) continue;
    const std::string program = name.substr(0, at);
    const std::string command = t.at("command").at(0).get<std::string>();
    EXPECT_EQ(command.substr(command.size() - program.size() - 1), "/" + program) << name;
    const auto value = [&](const std::string& key) {
      const std::size_t k = environment.find(key + "=");
      return k == std::string::npos ? -1 : std::stoi(environment.substr(k + key.size() + 1));
    };
    EXPECT_TRUE(shard_indices[program].insert(value("GTEST_SHARD_INDEX")).second) << name;
    shard_totals[program] = value("GTEST_TOTAL_SHARDS");
  }
  // This build is the asan preset's: it has shards.
  if (std::string(BEACHBALL_CXX_FLAGS) ==
      resolved(all, "asan").at("cacheVariables").value("CMAKE_CXX_FLAGS", "")) {
    EXPECT_FALSE(shard_indices.empty());
  }
  for (const auto& [label, seen] : kinds) EXPECT_EQ(seen.size(), 1u) << label;
  EXPECT_FALSE(kinds["cli"].count("shard")) << "the program-starting tests stay one per entry";
  for (const auto& [program, indices] : shard_indices) {
    std::set<int> every;
    for (int i = 0; i < shard_totals[program]; ++i) every.insert(i);
    EXPECT_EQ(indices, every) << program;
  }
}

TEST(Presets, EveryPresetUsesNinja) {
  const json all = presets();
  for (const json& p : all.at("configurePresets")) {
    const std::string name = p.at("name").get<std::string>();
    EXPECT_EQ(resolved(all, name).value("generator", ""), "Ninja") << name;
  }
}

}  // namespace
}  // namespace bb
