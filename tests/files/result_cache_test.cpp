// Kept results: an entry reads back as stored; a truncated, damaged or foreign entry is a
// miss and the next store replaces it; two processes storing and loading the same keys at
// once only ever read whole entries; pruning removes the entries used longest ago, and
// nothing in the folder that is not one of its entries, but what a killed store left; an
// entry is never read for another key; a folder that cannot keep results says why.
#include "files/result_cache.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
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
  const std::string whole = test::bytes(entry_path(folder, kKey));
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

// An entry copied under another key, its key line rewritten to that key, is not that key's:
// its checksum covers the key it was stored under.
TEST(ResultCache, AnEntryWhoseKeyLineWasRewrittenIsAMiss) {
  const std::string folder = test::fresh_dir("result_cache_rewritten");
  const ResultCache cache(folder, 1 << 20);
  ASSERT_TRUE(cache.store(kKey, "the results of one run"));
  const std::string other = digest("another run");
  std::string rewritten = test::bytes(entry_path(folder, kKey));
  rewritten.replace(rewritten.find(kKey), kKey.size(), other);
  std::ofstream(entry_path(folder, other), std::ios::binary) << rewritten;
  EXPECT_FALSE(cache.load(other));
  EXPECT_EQ(cache.damaged_entries(), std::vector<std::string>{other + ".entry"});
  EXPECT_EQ(cache.load(kKey), "the results of one run");
}

// A store killed between linking its entry under a name of its own and renaming it into
// place leaves "<key>.entry.<token>": prune removes it once its writer is gone (the lock a
// writer holds is free), never while its writer lives, and never a user's file of that name.
TEST(ResultCache, PruneRemovesWhatAKilledStoreLeft) {
  const std::string folder = test::fresh_dir("result_cache_killed_store");
  const ResultCache cache(folder, 1 << 20);
  ASSERT_TRUE(cache.store(kKey, "bytes"));
  const std::string whole = test::bytes(entry_path(folder, kKey));
  const std::string left = entry_path(folder, digest("killed")) + ".0123456789abcdef";
  const std::string live = entry_path(folder, digest("storing")) + ".fedcba9876543210";
  const std::string users = entry_path(folder, digest("user")) + ".0000000000000000";
  std::ofstream(left, std::ios::binary) << whole;
  std::ofstream(live, std::ios::binary) << whole;
  std::ofstream(users) << "a user's file";
  const int writer = open(live.c_str(), O_RDONLY);
  ASSERT_EQ(flock(writer, LOCK_EX | LOCK_NB), 0);
  EXPECT_EQ(cache.prune(), 1);
  close(writer);
  EXPECT_FALSE(fs::exists(left));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(users));
  EXPECT_EQ(cache.load(kKey), "bytes");
}

// A folder that cannot keep results says why: a file, a folder of another user, one that
// cannot be written (a user's own; root writes anywhere, so each where it can be made).
TEST(ResultCache, AFolderThatCannotKeepResultsSaysWhy) {
  const std::string dir = test::fresh_dir("result_cache_unusable");
  EXPECT_EQ(ResultCache(dir + "/new", 0).problem(), "");
  EXPECT_TRUE(fs::is_directory(dir + "/new"));
  std::ofstream(dir + "/file") << "a file";
  EXPECT_EQ(ResultCache(dir + "/file", 0).problem(), "it is not a folder");
  fs::create_directories(dir + "/theirs");
  if (geteuid() == 0) {
    ASSERT_EQ(chown((dir + "/theirs").c_str(), 65534, 65534), 0);
    EXPECT_EQ(ResultCache(dir + "/theirs", 0).problem(), "it belongs to another user");
  } else {
    fs::permissions(dir + "/theirs", fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_NE(ResultCache(dir + "/theirs", 0).problem().find("cannot be written"),
              std::string::npos);
    fs::permissions(dir + "/theirs", fs::perms::owner_all);
  }
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
