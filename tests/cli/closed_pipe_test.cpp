// A reader that went away (`beachball list 2>&1 | head`) stops every command that prints
// with 128 + SIGPIPE = 141, as docs/design.md promises, whether stderr went with stdout
// (nothing can be said then) or not (it says so on stderr). The pipe here is closed before
// the program starts, so every write fails, whatever the timing: `list` used to abort
// (exit 134, std::system_error thrown while saying so on the closed stderr), and a command
// whose few lines stayed in stdout's buffer exited 0.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

struct Ended {
  int code = -1;     ///< exit code, or 128 + the signal that ended it
  std::string said;  ///< stderr, when it went to a file
};

/// `beachball ARGS` with stdout into a pipe nobody reads (its read end closed first);
/// stderr into the same pipe with `both`, else into a file that is read back.
Ended with_closed_reader(const std::vector<std::string>& args, bool both) {
  int ends[2];
  if (pipe(ends) != 0) return {};
  close(ends[0]);
  const std::string log = test::fresh_dir("closed_pipe_stderr.txt");
  const pid_t pid = fork();
  if (pid == 0) {
    // The default action for SIGPIPE, as a shell gives it (the program sets its own).
    signal(SIGPIPE, SIG_DFL);
    dup2(ends[1], STDOUT_FILENO);
    if (both) {
      dup2(ends[1], STDERR_FILENO);
    } else {
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, STDERR_FILENO);
    }
    test::exec_beachball(args);
  }
  close(ends[1]);
  Ended ended;
  ended.code = test::wait_for(pid);
  if (!both) ended.said = test::bytes(log);
  return ended;
}

TEST(ClosedPipe, EveryCommandThatPrintsStopsWith141) {
  const std::string dir = test::fresh_dir("closed_pipe");
  const std::string cases = test::write_case(dir, "a.toml", test::minimal_case("a"));
  // A shard of the report, for merge.
  const test::Outcome shard = test::beachball(
      "report " + cases + " --no-cost --cache off --shard 1/1 --out " + dir + "/shard");
  ASSERT_EQ(shard.exit_code, 0) << shard.out;
  const std::vector<std::vector<std::string>> commands = {
      {"list"},
      {"list", cases},
      {"run", cases, "--no-cost", "--cache", "off", "--out", dir + "/run"},
      {"check", cases, "--cache", "off"},
      {"stability", cases, "--backends", "course/rk4", "--cache", "off", "--out", dir + "/stab"},
      {"report", cases, "--no-cost", "--cache", "off", "--out", dir + "/report"},
      {"merge", dir + "/shard", "--cases", cases, "--out", dir + "/merged"},
  };
  for (const bool both : {true, false})
    for (const std::vector<std::string>& args : commands) {
      std::string line;
      for (const std::string& a : args) line += a + " ";
      SCOPED_TRACE(line + (both ? "(stdout and stderr closed)" : "(stdout closed)"));
      // Each command writes its folder anew.
      for (const char* sub : {"/run", "/stab", "/report", "/merged"}) fs::remove_all(dir + sub);
      const Ended ended = with_closed_reader(args, both);
      EXPECT_EQ(ended.code, 128 + SIGPIPE);
      if (!both) {
        EXPECT_NE(ended.said.find("interrupted by signal 13"), std::string::npos) << ended.said;
      }
    }
}

}  // namespace
}  // namespace bb
