// A kept run's key is made of everything that decides it: the same run has the same key, and
// a change of the case's text, of what was changed in it (a sweep's point), of what is kept,
// of the backend, of the step or of the engine's plugin makes another. A scene made in code
// has no text and no key: its runs are never kept. A shard keeps every outcome, for its
// merge alone.
#include "run/run_cache.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>

#include "study/case_error.hpp"
#include "support/course_support.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(RunCache, EveryPartOfWhatDecidesARunIsInItsKey) {
  const std::string plugins = test::fresh_dir("run_cache_plugins");
  std::filesystem::create_directories(plugins);
  const std::string plugin = plugins + "/" + plugin_file_name("course/rk4");
  std::ofstream(plugin) << "one build";
  setenv("BEACHBALL_PLUGIN_DIR", plugins.c_str(), 1);
  const Scene scene = test::scene_from(test::minimal_case("kept"));
  const Backend& rk4 = test::course("rk4");
  const Backend& euler = test::course("explicit-euler");
  RunCache cache(test::fresh_dir("run_cache"), false);
  const std::string key = cache.key(scene, "accuracy", rk4, 0.1);
  ASSERT_EQ(key.size(), 32u);
  EXPECT_EQ(cache.key(scene, "accuracy", rk4, 0.1), key);

  Scene edited = test::scene_from(test::minimal_case("kept") + "\n# a comment\n");
  Scene point = scene;
  point.variant = "sweep mass = 2";
  for (const std::string& other :
       {cache.key(edited, "accuracy", rk4, 0.1), cache.key(point, "accuracy", rk4, 0.1),
        cache.key(scene, "stability trial", rk4, 0.1), cache.key(scene, "accuracy", euler, 0.1),
        cache.key(scene, "accuracy", rk4, 0.05),
        cache.key(scene, "accuracy", rk4, std::nextafter(0.1, 1.0)),
        cache.key(scene, "accuracy", rk4, std::nullopt)})
    EXPECT_NE(other, key);

  // Another build of the backend's plugin: another key (a new cache reads the build anew).
  std::ofstream(plugin) << "another build";
  EXPECT_NE(RunCache(test::fresh_dir("run_cache"), false).key(scene, "accuracy", rk4, 0.1), key);
  unsetenv("BEACHBALL_PLUGIN_DIR");

  Scene made_in_code = scene;
  made_in_code.source.clear();
  EXPECT_EQ(cache.key(made_in_code, "accuracy", rk4, 0.1), "");
}

TEST(RunCache, FreshRunsEverythingAndCountsWhatWasReused) {
  const std::string folder = test::fresh_dir("run_cache_counts");
  const std::string key = digest("a run");
  RunCache kept(folder, false);
  EXPECT_FALSE(kept.find(key));
  kept.keep(key, "bytes", true);
  EXPECT_EQ(kept.find(key), "bytes");
  EXPECT_FALSE(kept.find(""));
  EXPECT_EQ(kept.reused(), 1);
  EXPECT_EQ(kept.ran(), 2);
  RunCache fresh(folder, true);
  EXPECT_FALSE(fresh.find(key));
  EXPECT_EQ(fresh.reused(), 0);
  EXPECT_EQ(fresh.ran(), 1);
}

// A shard keeps a crash or a timeout too, apart from the results a run reuses: a run in the
// same folder runs it again, a merge of the shards reads it.
TEST(RunCache, AShardKeepsEveryOutcomeForItsMergeAlone) {
  const std::string folder = test::fresh_dir("run_cache_shard");
  const std::string repeated = digest("an ok run"), once = digest("a timeout");
  RunCache shard(folder, false);
  shard.keep_every_outcome();
  shard.keep(repeated, "ok", true);
  shard.keep(once, "timed out", false);
  EXPECT_EQ(shard.find(repeated), "ok");
  EXPECT_FALSE(shard.find(once));
  RunCache own(folder, false);
  own.keep(digest("another timeout"), "timed out", false);
  RunCache merge(std::map<int, std::string>{{1, folder}});
  EXPECT_EQ(merge.find(repeated), "ok");
  EXPECT_EQ(merge.find(once), "timed out");
  EXPECT_THROW(merge.find(digest("another timeout")), CaseError);
}

// Runs that belong together (a backend's runs measured against its own finest one, which
// only a run anew writes whole) are reused all together or not at all.
TEST(RunCache, RunsThatBelongTogetherAreReusedOnlyTogether) {
  const std::string folder = test::fresh_dir("run_cache_together");
  const std::vector<std::string> keys = {digest("finest"), digest("coarse")};
  RunCache kept(folder, false);
  kept.keep(keys[0], "the finest", true);
  EXPECT_FALSE(kept.find_all(keys));
  EXPECT_EQ(kept.ran(), 2);
  EXPECT_EQ(kept.reused(), 0);
  kept.keep(keys[1], "a coarser one", true);
  const auto both = kept.find_all(keys);
  ASSERT_TRUE(both);
  EXPECT_EQ(*both, (std::vector<std::string>{"the finest", "a coarser one"}));
  EXPECT_EQ(kept.reused(), 2);
  EXPECT_FALSE(RunCache(folder, true).find_all(keys));
  // A run that is never kept (no key) keeps its companions from being reused.
  EXPECT_FALSE(kept.find_all({keys[0], ""}));
}

}  // namespace
}  // namespace bb
