// Kept results: an entry reads back as stored; a truncated, damaged or foreign entry is a
// miss and the next store replaces it; two processes storing and loading the same keys at
// once only ever read whole entries; pruning removes the entries used longest ago, and
// nothing in the folder that is not one of its entries.
#include "files/result_cache.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "support/program.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

const std::string kKey = digest("a run");

std::string entry_path(const std::string& folder, const std::string& key) {
  return folder + "/" + key + ".entry";
}

TEST(ResultCache, AnEntryReadsBackAndADamagedOneIsAMissThatTheNextStoreReplaces) {
  const std::string folder = test::fresh_dir("result_cache");
  const ResultCache cache(folder, 1 << 20);
  EXPECT_FALSE(cache.load(kKey));
  const std::string bytes = std::string("payload\0with a zero", 19);
  ASSERT_TRUE(cache.store(kKey, bytes));
  EXPECT_EQ(cache.load(kKey), bytes);
  const std::string whole = test::file_bytes(entry_path(folder, kKey));
  // Cut short, one byte changed, another program's file under the name: each a miss.
  for (const std::string& damaged :
       {whole.substr(0, whole.size() - 3), whole.substr(0, whole.size() - 1) + "X",
        std::string("not beachball's")}) {
    std::ofstream(entry_path(folder, kKey), std::ios::binary | std::ios::trunc) << damaged;
    EXPECT_FALSE(cache.load(kKey));
    ASSERT_TRUE(cache.store(kKey, bytes));
    EXPECT_EQ(cache.load(kKey), bytes);
  }
  // An entry under another key is not this one, even with the same bytes.
  fs::copy_file(entry_path(folder, kKey), entry_path(folder, digest("another run")));
  EXPECT_FALSE(cache.load(digest("another run")));
  // Nothing is written where the key is not one.
  EXPECT_FALSE(cache.store("../escape", bytes));
  EXPECT_FALSE(fs::exists(folder + "/../escape.entry"));
}

TEST(ResultCache, TwoProcessesAtOnceOnlyEverReadWholeEntries) {
  const std::string folder = test::fresh_dir("result_cache_shared");
  const std::string big(1 << 18, 'x');
  std::vector<pid_t> children;
  for (int p = 0; p < 2; ++p) {
    const pid_t pid = fork();
    if (pid == 0) {
      const ResultCache cache(folder, 1ULL << 30);
      int bad = 0;
      for (int i = 0; i < 100; ++i) {
        const std::string key = digest(std::to_string(i % 5));
        const std::string bytes = std::to_string(i % 5) + big;
        cache.store(key, bytes);
        if (const auto read = cache.load(key); read && *read != bytes) ++bad;
      }
      _exit(bad == 0 ? 0 : 1);
    }
    children.push_back(pid);
  }
  for (pid_t pid : children) EXPECT_EQ(test::wait_for(pid), 0);
  const ResultCache cache(folder, 1ULL << 30);
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(cache.load(digest(std::to_string(k))), std::to_string(k) + big);
}

TEST(ResultCache, PruningRemovesTheEntriesUsedLongestAgoAndNothingElse) {
  const std::string folder = test::fresh_dir("result_cache_prune");
  const ResultCache cache(folder, 2500);
  const std::string bytes(1000, 'b');
  for (const char* run : {"first", "second", "third"}) {
    ASSERT_TRUE(cache.store(digest(run), bytes));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // The first is used again: the second is now the one used longest ago.
  ASSERT_TRUE(cache.load(digest("first")));
  // A user's file, and one named like an entry that is not one: never removed.
  std::ofstream(folder + "/notes.txt") << std::string(5000, 'n');
  std::ofstream(entry_path(folder, digest("foreign"))) << std::string(5000, 'f');
  EXPECT_EQ(cache.prune(), 1);
  EXPECT_FALSE(cache.load(digest("second")));
  EXPECT_TRUE(cache.load(digest("first")));
  EXPECT_TRUE(cache.load(digest("third")));
  EXPECT_TRUE(fs::exists(folder + "/notes.txt"));
  EXPECT_TRUE(fs::exists(entry_path(folder, digest("foreign"))));
}

TEST(ResultCache, ADigestTellsApartInputsThatDiffer) {
  EXPECT_EQ(digest("abc").size(), 32u);
  EXPECT_EQ(digest("abc"), digest("abc"));
  EXPECT_NE(digest("abc"), digest("abd"));
  EXPECT_NE(digest(""), digest(std::string(1, '\0')));
}

}  // namespace
}  // namespace bb
