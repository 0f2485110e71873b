// Running the `beachball` program from a test: its exit code and everything it printed,
// or a running one to signal; and a folder's files as bytes, to compare before and after.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "support/test_support.hpp"

namespace bb::test {

struct Outcome {
  int exit_code = -1;
  std::string out;  ///< stdout and stderr together
};

/// Runs `command` through the shell and waits for it: its exit code and its output (stdout
/// and stderr).
inline Outcome shell(const std::string& command) {
  Outcome o;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::array<char, 4096> buffer{};
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    o.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

/// Runs `beachball ARGS` through the shell and waits for it; `shell_prefix` runs first in
/// the same shell (a `ulimit`, say), and the program is exec'ed after it.
inline Outcome beachball(const std::string& args, const std::string& shell_prefix = "") {
  return shell(shell_prefix + " exec " + std::string(BEACHBALL_PROGRAM) + " " + args);
}

/// A path under the test's temporary folder that does not exist yet.
inline std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/beachball_" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

/// Writes `text` to `dir/file` (creating `dir`) and returns the path.
inline std::string write_case(const std::string& dir, const std::string& file,
                              const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + file;
  std::ofstream(path) << text;
  return path;
}

/// Replaces this (forked) process with `beachball ARGS`; exit code 127 where it cannot start.
[[noreturn]] inline void exec_beachball(const std::vector<std::string>& args) {
  std::vector<const char*> argv = {BEACHBALL_PROGRAM};
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  execv(BEACHBALL_PROGRAM, const_cast<char* const*>(argv.data()));
  _exit(127);
}

/// Starts `beachball ARGS` without waiting, its output to `log`; returns its pid.
inline pid_t start_beachball(const std::vector<std::string>& args, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    exec_beachball(args);
  }
  return pid;
}

/// Waits for `pid`: its exit code, or 128 + the signal that ended it.
inline int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Every file under `folder` (path relative to it) with its bytes.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& folder) {
  std::map<std::string, std::string> out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      out[std::filesystem::relative(entry.path(), folder).string()] = bytes(entry.path());
  return out;
}

/// Whether `name` is one of beachball's temporaries: a staging folder, a report built
/// beside its folder, a scratch folder, a marker, a file being replaced. Its record of
/// what it wrote (.beachball-manifest) is not a temporary.
inline bool beachball_temporary(const std::string& name) {
  return name.find("beachball-") != std::string::npos && name != ".beachball-manifest";
}

/// Names in `folder` that are beachball's temporaries, one string.
inline std::string temporaries_in(const std::filesystem::path& folder) {
  std::string found;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (beachball_temporary(entry.path().filename().string()))
      found += entry.path().filename().string() + " ";
  return found;
}

/// The numbers of "kept results: R reused, N run" in the program's output: {R, N}, or
/// {-1, -1} when it says nothing of them.
inline std::pair<int, int> kept_counts(const std::string& out) {
  const auto at = out.find("kept results: ");
  int reused = -1, ran = -1;
  if (at == std::string::npos ||
      std::sscanf(out.c_str() + at, "kept results: %d reused, %d run", &reused, &ran) != 2)
    return {-1, -1};
  return {reused, ran};
}

}  // namespace bb::test
