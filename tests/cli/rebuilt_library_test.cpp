// A result is never served from another build. The kept results' key covers the bytes of
// every shared library the program loads, found from the process itself, not only the
// program and its plugins. The build makes a second libbb_physics.so (the same sources and
// one more translation unit, so other bytes; tests/CMakeLists.txt); the program run with it
// first in its library path (LD_LIBRARY_PATH is searched before the build's RUNPATH) loads
// it instead of its own, so it is the program after a rebuild of that one library: it
// reruns every run, and a merge refuses shards made by it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// The shell words that run the program with the rebuilt libbb_physics.so.
const std::string kRebuilt =
    std::string("export LD_LIBRARY_PATH=") + BEACHBALL_REBUILT_LIBRARY_DIR + ";";

TEST(RebuiltLibrary, ARebuiltPhysicsLibraryRerunsEveryRun) {
  ASSERT_TRUE(fs::exists(std::string(BEACHBALL_REBUILT_LIBRARY_DIR) + "/libbb_physics.so"));
  const std::string dir = test::fresh_dir("rebuilt_library");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  const auto run = [&](const std::string& out, const std::string& prefix = "") {
    return test::beachball("run " + a + " --no-cost --backends reference,course/rk4 --out " + dir +
                               "/" + out + " --cache " + dir + "/cache",
                           prefix);
  };
  const test::Outcome first = run("first");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const int all = test::kept_counts(first.out).second;
  ASSERT_GT(all, 0) << first.out;
  // The same build again: everything reused.
  EXPECT_EQ(test::kept_counts(run("again").out), std::make_pair(all, 0));
  // The rebuilt library: nothing reused, and the same numbers (its code computes alike).
  const test::Outcome rebuilt = run("rebuilt", kRebuilt);
  ASSERT_EQ(rebuilt.exit_code, 0) << rebuilt.out;
  EXPECT_EQ(test::kept_counts(rebuilt.out), std::make_pair(0, all)) << rebuilt.out;
  EXPECT_EQ(test::bytes(dir + "/rebuilt/a.json"), test::bytes(dir + "/first/a.json"));
  // Back to the build's own library: its results are still kept.
  EXPECT_EQ(test::kept_counts(run("back").out), std::make_pair(all, 0));
}

TEST(RebuiltLibrary, AMergeRefusesShardsMadeWithAnotherLibrary) {
  const std::string dir = test::fresh_dir("rebuilt_library_merge");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  for (int i = 1; i <= 2; ++i) {
    const test::Outcome o =
        test::beachball("run " + a + " --no-cost --backends course/rk4 --shard " +
                            std::to_string(i) + "/2 --out " + dir + "/shard" + std::to_string(i),
                        kRebuilt);
    ASSERT_EQ(o.exit_code, 0) << o.out;
  }
  const test::Outcome merged = test::beachball("merge " + dir + "/shard1 " + dir +
                                               "/shard2 --cases " + a + " --out " + dir + "/out");
  EXPECT_EQ(merged.exit_code, 2) << merged.out;
  EXPECT_NE(merged.out.find("was made by another build"), std::string::npos) << merged.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  // The same build merges them.
  const test::Outcome same = test::beachball(
      "merge " + dir + "/shard1 " + dir + "/shard2 --cases " + a + " --out " + dir + "/out",
      kRebuilt);
  EXPECT_EQ(same.exit_code, 0) << same.out;
}

}  // namespace
}  // namespace bb
