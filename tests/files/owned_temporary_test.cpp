// A temporary folder beachball owns is removed with its marker last: a kill at any moment of
// the removal leaves either nothing or a folder still marked, which the next run removes;
// never an unmarked folder that nobody can prove is beachball's.
#include "files/owned_temporary.hpp"

#include <gtest/gtest.h>
#include <signal.h>
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

constexpr const char* kPrefix = ".beachball-staging-";

/// Forks a child that fills an owned temporary folder in `parent` with many files, says so
/// on a pipe, then removes the folder; the child is killed `delay` after it says so.
void kill_during_removal(const std::string& parent, std::chrono::microseconds delay) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    OwnedTemporary folder(parent, kPrefix);
    // Files beside the marker, so that a removal in directory order reaches the marker at
    // some random point among them.
    for (int i = 0; i < 1000; ++i) std::ofstream(folder.path() + "/f" + std::to_string(i)) << i;
    if (write(fds[1], "r", 1) != 1) _exit(1);
    folder.remove();
    _exit(0);
  }
  close(fds[1]);
  char ready = 0;
  ASSERT_EQ(read(fds[0], &ready, 1), 1);
  close(fds[0]);
  std::this_thread::sleep_for(delay);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
}

TEST(OwnedTemporary, AKillDuringItsRemovalLeavesItMarkedForTheNextRun) {
  const std::string parent = test::fresh_dir("owned_removal");
  fs::create_directories(parent);
  int interrupted = 0;
  for (int attempt = 0; attempt < 4; ++attempt) {
    kill_during_removal(parent, std::chrono::microseconds(2000 + 4000 * attempt));
    for (const auto& entry : fs::directory_iterator(parent)) {
      ++interrupted;
      EXPECT_TRUE(fs::is_regular_file(entry.path() / kOwnerMarker))
          << entry.path() << " was left without its marker after a kill during its removal";
    }
    remove_abandoned_temporaries(parent, kPrefix);
    EXPECT_TRUE(fs::is_empty(parent)) << "the next run did not finish the removal";
  }
  // The kills must have landed during removals for the test to say anything.
  EXPECT_GT(interrupted, 0);
}

TEST(OwnedTemporary, AUsersFolderOfTheSameNameIsLeftAlone) {
  const std::string parent = test::fresh_dir("owned_users");
  fs::create_directories(parent);
  const std::string mine = parent + "/" + kPrefix + "0123456789abcdef";
  fs::create_directories(mine);
  std::ofstream(mine + "/thesis.txt") << "mine";
  EXPECT_EQ(remove_abandoned_temporaries(parent, kPrefix), 0);
  EXPECT_TRUE(fs::exists(mine + "/thesis.txt"));
}

}  // namespace
}  // namespace bb
