// An interrupted report leaves the previous one untouched; a second writer is refused.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::bytes;

/// Starts `beachball report --out out` with output to `log`; returns the child's pid.
pid_t start_report(const std::string& out, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    execl(BEACHBALL_PROGRAM, BEACHBALL_PROGRAM, "report", "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

TEST(Interrupt, SigtermDuringReportLeavesThePreviousReportUntouched) {
  const std::string out = ::testing::TempDir() + "/interrupted_report";
  fs::remove_all(out);
  fs::create_directories(out);
  // A previous report, as far as this test cares.
  std::ofstream(out + "/README.md") << "# beachball report\nthe previous one\n";
  std::ofstream(out + "/drag_fall.json") << "{\"previous\": true}\n";
  const std::string log = ::testing::TempDir() + "/interrupted_report.log";
  const pid_t pid = start_report(out, log);
  // The full suite with its cost pass takes several seconds; stop it well inside them.
  usleep(1500 * 1000);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << bytes(log);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << bytes(log);
  EXPECT_NE(bytes(log).find("interrupted by signal 15"), std::string::npos) << bytes(log);
  EXPECT_NE(bytes(log).find("stopped during"), std::string::npos) << bytes(log);
  EXPECT_EQ(bytes(out + "/README.md"), "# beachball report\nthe previous one\n");
  EXPECT_EQ(bytes(out + "/drag_fall.json"), "{\"previous\": true}\n");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_FALSE(test::beachball_temporary(entry.path().filename().string())) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 2);
}

/// Whether a trajectory file is being written in `out`: a .csv in a batch's staging folder.
bool writing_trajectories(const std::string& out) {
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(out, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->path().extension() == ".csv" &&
        it->path().string().find("/.beachball-staging-") != std::string::npos)
      return true;
  return false;
}

TEST(Interrupt, SigtermWhileRunsWriteTrajectoriesLeavesNoneAndTheEarlierSetUntouched) {
  const std::string dir = test::fresh_dir("interrupted_trajectories");
  const std::string out = dir + "/out";
  // An earlier set of the case, its trajectories included, from a short version of it.
  const std::string quick =
      test::write_case(dir + "/quick", "slow.toml", test::minimal_case("slow"));
  const test::Outcome first = test::beachball(
      "run " + quick + " --no-cost --backends course/explicit-euler --trajectories --out " + out);
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const auto before = test::snapshot(out);
  // The slow version: its runs write for minutes; stopped once their files are under way.
  const std::string slow = test::write_case(dir, "slow.toml", test::slow_case("slow"));
  const pid_t pid = test::start_beachball({"run", slow, "--no-cost", "--backends",
                                           "course/explicit-euler", "--trajectories", "--out", out},
                                          dir + "/slow.log");
  int status = 0;
  while (!writing_trajectories(out) && waitpid(pid, &status, WNOHANG) == 0) usleep(1000);
  ASSERT_TRUE(writing_trajectories(out)) << test::bytes(dir + "/slow.log");
  kill(pid, SIGTERM);
  EXPECT_EQ(test::wait_for(pid), 128 + SIGTERM) << test::bytes(dir + "/slow.log");
  EXPECT_EQ(test::snapshot(out), before) << "a trajectory file, or a change to the earlier set";
  EXPECT_EQ(test::temporaries_in(out), "");
}

TEST(Interrupt, ASecondWriterOfTheSameFolderIsRefused) {
  const std::string out = ::testing::TempDir() + "/locked_report";
  fs::create_directories(out);
  // Hold the folder the way a running beachball does.
  const int fd = open(out.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string log = ::testing::TempDir() + "/locked_report.log";
  const pid_t pid = start_report(out, log);
  int status = 0;
  waitpid(pid, &status, 0);
  close(fd);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(bytes(log).find("another beachball is writing this folder"), std::string::npos)
      << bytes(log);
  EXPECT_TRUE(fs::is_empty(out));
}

}  // namespace
}  // namespace bb
