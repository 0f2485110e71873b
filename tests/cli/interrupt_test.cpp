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
