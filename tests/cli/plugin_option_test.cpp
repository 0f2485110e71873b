// `--plugin PATH.so` and $BEACHBALL_PLUGIN_PATH end to end, with plugins built beside the
// program from tests/plugins/test_plugin.cpp: a working plugin's backend is listed with what
// it declares and runs as a row like a built-in's (its results kept under its file's bytes);
// a plugin that crashes as a run starts or at a step is a row `crashed`; a missing file, a
// file that is not a shared object, another interface version, no version symbol and a name
// another backend has are each refused with the reason, exit 2, before any work.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::beachball;
using test::Outcome;

/// A built test plugin: tests/plugins/test_plugin.cpp built as beachball-<variant>.so.
std::string plugin(const std::string& variant) {
  return std::string(BEACHBALL_TEST_PLUGIN_DIR) + "/beachball-" + variant + ".so";
}

/// A ball falling in a vacuum: what every test plugin can run.
const char* kFallCase = R"(name = "fall"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
)";

/// The rows of `backend` in `dir`/fall.json.
std::vector<nlohmann::json> rows(const std::string& dir, const std::string& backend) {
  const auto j = nlohmann::json::parse(std::ifstream(dir + "/fall.json"));
  std::vector<nlohmann::json> out;
  for (const auto& run : j["runs"])
    if (run["backend"] == backend) out.push_back(run);
  return out;
}

TEST(PluginOption, ItsBackendIsListedAndRunsAsARow) {
  const std::string dir = test::fresh_dir("plugin_runs");
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  const Outcome list = beachball("list " + c + " --plugin " + plugin("falling"));
  ASSERT_EQ(list.exit_code, 0) << list.out;
  // Its name, its file, its library and version, its features, and that it runs the case.
  EXPECT_NE(list.out.find("test/falling"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("plugin " + plugin("falling") + " (test 0): 3d, gravity"),
            std::string::npos)
      << list.out;
  const Outcome run =
      beachball("run " + c + " --plugin " + plugin("falling") +
                " --backends test/falling --no-cost --cache off --out " + dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const auto mine = rows(dir + "/out", "test/falling");
  ASSERT_EQ(mine.size(), 2u);  // one row per dt
  for (const auto& r : mine) {
    EXPECT_EQ(r["status"], "ok") << r.dump();
    // The closed form of a fall, against the reference: to the reference's tolerance.
    EXPECT_LT(r["errors"]["position_max"].get<double>(), 1e-6) << r.dump();
  }
}

// A plugin may give several backends (plugin interface 2): each is listed and runs as a row.
TEST(PluginOption, EachBackendOfAPluginOfSeveralIsARow) {
  const std::string dir = test::fresh_dir("plugin_pair");
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  const Outcome list = beachball("list " + c + " --plugin " + plugin("pair"));
  ASSERT_EQ(list.exit_code, 0) << list.out;
  const Outcome run = beachball("run " + c + " --plugin " + plugin("pair") +
                                " --no-cost --cache off --out " + dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  for (const char* backend : {"test/pair-a", "test/pair-b"}) {
    EXPECT_NE(list.out.find(std::string(backend) + " "), std::string::npos) << list.out;
    const auto mine = rows(dir + "/out", backend);
    ASSERT_EQ(mine.size(), 2u) << backend;  // one row per dt
    for (const auto& r : mine) {
      EXPECT_EQ(r["status"], "ok") << r.dump();
      EXPECT_LT(r["errors"]["position_max"].get<double>(), 1e-6) << r.dump();
    }
  }
}

TEST(PluginOption, ACrashAsARunStartsOrAtAStepIsARowCrashed) {
  const std::string dir = test::fresh_dir("plugin_crash");
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  const Outcome run = beachball("run " + c + " --plugin " + plugin("crash-start") + " --plugin " +
                                plugin("crash-step") +
                                " --backends test/crash-start,test/crash-step,course/rk4 "
                                "--no-cost --cache off --out " +
                                dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  for (const char* backend : {"test/crash-start", "test/crash-step"}) {
    const auto mine = rows(dir + "/out", backend);
    ASSERT_EQ(mine.size(), 2u) << backend;
    for (const auto& r : mine) EXPECT_EQ(r["status"], "crashed") << r.dump();
  }
  // The other rows are untouched by the crashes.
  for (const auto& r : rows(dir + "/out", "course/rk4")) EXPECT_EQ(r["status"], "ok") << r.dump();
}

/// `run` with `plugin_args` must stop at once: exit 2, `why` said, nothing written.
void refused(const std::string& name, const std::string& plugin_args, const std::string& why,
             const std::string& env = "") {
  const std::string dir = test::fresh_dir(name);
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  const Outcome o =
      beachball("run " + c + " " + plugin_args + " --no-cost --out " + dir + "/out", env);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find(why), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/out")) << o.out;
}

TEST(PluginOption, AnotherInterfaceVersionIsRefusedWithBothVersions) {
  // The test plugin exports this program's version plus one.
  refused("plugin_version", "--plugin " + plugin("next-version"),
          plugin("next-version") + ": was built against beachball plugin interface ");
  const Outcome o = beachball("list --plugin " + plugin("next-version"));
  const std::size_t at = o.out.find("plugin interface ");
  ASSERT_NE(at, std::string::npos) << o.out;
  const int theirs = std::stoi(o.out.substr(at + 17));
  EXPECT_NE(o.out.find("this beachball has " + std::to_string(theirs - 1) + ": rebuild it"),
            std::string::npos)
      << o.out;
}

TEST(PluginOption, APluginWithoutTheVersionSymbolIsRefused) {
  refused("plugin_no_version", "--plugin " + plugin("no-version"),
          "has no beachball_plugin_interface_version");
}

TEST(PluginOption, AMissingFileOrOneThatIsNotASharedObjectIsRefused) {
  refused("plugin_missing", "--plugin /nonexistent/beachball-x.so",
          "/nonexistent/beachball-x.so: no such plugin file");
  const std::string dir = test::fresh_dir("plugin_text");
  const std::string text = test::write_case(dir, "beachball-text.so", "not a shared object\n");
  refused("plugin_not_elf", "--plugin " + text, text + ": failed to load: ");
}

TEST(PluginOption, ANameAnotherBackendHasIsRefused) {
  refused("plugin_clash", "--plugin " + plugin("clash"), "is a built-in backend's name");
  // Two files whose backends share a name.
  const std::string dir = test::fresh_dir("plugin_twice");
  fs::create_directories(dir);
  fs::copy_file(plugin("falling"), dir + "/beachball-copy.so");
  refused("plugin_twice_run",
          "--plugin " + plugin("falling") + " --plugin " + dir + "/beachball-copy.so",
          "is the name of the backend of " + plugin("falling"));
}

TEST(PluginOption, TheSearchPathLoadsEveryPluginInItsFolders) {
  const std::string dir = test::fresh_dir("plugin_path");
  fs::create_directories(dir + "/plugins");
  fs::copy_file(plugin("falling"), dir + "/plugins/beachball-falling.so");
  const Outcome list =
      beachball("list", "BEACHBALL_PLUGIN_PATH=/nonexistent-not-first:" + dir + "/plugins");
  // A folder of the path that is not one is bad input too.
  EXPECT_EQ(list.exit_code, 2) << list.out;
  EXPECT_NE(list.out.find("/nonexistent-not-first: is in $BEACHBALL_PLUGIN_PATH but is not a "
                          "folder"),
            std::string::npos)
      << list.out;
  const Outcome found = beachball("list", "BEACHBALL_PLUGIN_PATH=" + dir + "/plugins");
  EXPECT_EQ(found.exit_code, 0) << found.out;
  EXPECT_NE(found.out.find("test/falling"), std::string::npos) << found.out;
}

TEST(PluginOption, ItsKeptResultsAreKeptUnderItsFilesBytes) {
  const std::string dir = test::fresh_dir("plugin_cache");
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  fs::create_directories(dir + "/p");
  const std::string mine = dir + "/p/beachball-falling.so";
  fs::copy_file(plugin("falling"), mine);
  const auto run = [&] {
    return beachball("run " + c + " --plugin " + mine +
                     " --backends test/falling,course/rk4 --no-cost --cache " + dir +
                     "/cache --out " + dir + "/out");
  };
  const Outcome first = run();
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const auto counts = [](const Outcome& o) {
    const std::size_t at = o.out.find("kept results: ");
    EXPECT_NE(at, std::string::npos) << o.out;
    const std::string rest = at == std::string::npos ? "0 reused, 0 run" : o.out.substr(at + 14);
    return std::pair{std::stoi(rest), std::stoi(rest.substr(rest.find(", ") + 2))};
  };
  const auto [kept, ran] = counts(run());
  EXPECT_EQ(ran, 0);
  // The same plugin with other bytes (a rebuild): its two runs again, every other kept.
  std::ofstream(mine, std::ios::app) << "rebuilt";
  const Outcome rebuilt = run();
  ASSERT_EQ(rebuilt.exit_code, 0) << rebuilt.out;
  EXPECT_EQ(counts(rebuilt), std::pair(kept - 2, 2)) << rebuilt.out;
}

TEST(PluginOption, ShardsMergeWithTheSamePluginsOnly) {
  const std::string dir = test::fresh_dir("plugin_shards");
  const std::string c = test::write_case(dir, "fall.toml", kFallCase);
  const std::string with = " --plugin " + plugin("falling");
  for (const char* shard : {"1/2", "2/2"}) {
    const Outcome o =
        beachball("run " + c + with + " --backends test/falling,course/rk4 --no-cost --shard " +
                  shard + " --out " + dir + "/shard-" + shard[0]);
    ASSERT_EQ(o.exit_code, 0) << o.out;
  }
  const std::string shards = dir + "/shard-1 " + dir + "/shard-2 --cases " + c;
  const Outcome merged = beachball("merge " + shards + with + " --out " + dir + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  const auto mine = rows(dir + "/merged", "test/falling");
  ASSERT_EQ(mine.size(), 2u);
  for (const auto& r : mine) EXPECT_EQ(r["status"], "ok") << r.dump();
  // Without the plugin the build is another: refused before any work.
  const Outcome without = beachball("merge " + shards + " --out " + dir + "/without");
  EXPECT_EQ(without.exit_code, 2) << without.out;
  EXPECT_NE(without.out.find("was made by another build of beachball"), std::string::npos)
      << without.out;
}

}  // namespace
}  // namespace bb
