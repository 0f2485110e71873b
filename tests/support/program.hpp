// Running the `beachball` program from a test: its exit code and everything it printed.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace bb::test {

struct Outcome {
  int exit_code = -1;
  std::string out;  ///< stdout and stderr together
};

/// Runs `beachball ARGS` through the shell and waits for it; `shell_prefix` runs first in
/// the same shell (a `ulimit`, say), and the program is exec'ed after it.
inline Outcome beachball(const std::string& args, const std::string& shell_prefix = "") {
  const std::string command =
      shell_prefix + " exec " + std::string(BEACHBALL_PROGRAM) + " " + args + " 2>&1";
  Outcome o;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    o.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
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

}  // namespace bb::test
