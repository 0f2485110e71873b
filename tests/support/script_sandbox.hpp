// The repository's shell scripts run in a folder of their own, with stand-ins for what they
// call (cmake, ctest, scripts/setup, the program) that write each call to a log: what a
// script would build and configure, seen without building anything.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb::test {

class ScriptSandbox {
 public:
  explicit ScriptSandbox(const std::string& name) : root_(fresh_dir(name)) {
    namespace fs = std::filesystem;
    fs::create_directories(root_ + "/scripts");
    fs::create_directories(root_ + "/stand-ins");
    for (const char* script : {"build", "preset.sh", "report", "test"})
      fs::copy_file(source_path(std::string("scripts/") + script), root_ + "/scripts/" + script);
    executable("scripts/setup", "echo \"setup${*:+ $*}\" >> \"$CALLS\"");
    // A configure (cmake --preset P) leaves the cache Ninja's would, in the preset's folder.
    executable(
        "stand-ins/cmake",
        "echo \"cmake $*\" >> \"$CALLS\"\n"
        "if [ \"$1\" = --preset ]; then\n"
        "  dir=build; case \"$2\" in default|dev) ;; *) dir=build-$2 ;; esac\n"
        "  mkdir -p \"$dir\"; echo CMAKE_GENERATOR:INTERNAL=Ninja > \"$dir/CMakeCache.txt\"\n"
        "fi");
    executable("stand-ins/ctest", "echo \"ctest $*\" >> \"$CALLS\"");
    std::ofstream(root_ + "/dpkg-status") << "";
  }

  /// Runs `command` (a script, with its arguments) from the sandbox's root, `env` before it;
  /// the preset and options of the environment the tests run in (CI sets them) are not passed on.
  Outcome run(const std::string& command, const std::string& env = "") const {
    return shell("cd " + root_ +
                 " && unset BEACHBALL_PRESET BEACHBALL_CMAKE_ARGS && CALLS=" + root_ +
                 "/calls.log PATH=" + root_ + "/stand-ins:$PATH BEACHBALL_DPKG_STATUS=" + root_ +
                 "/dpkg-status " + env + " bash " + command);
  }

  /// Every call to a stand-in so far, one line each; `clear` forgets them.
  std::vector<std::string> calls() const {
    std::ifstream in(root_ + "/calls.log");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  void clear() const { std::filesystem::remove(root_ + "/calls.log"); }

  /// The configure calls (cmake --preset ...) among calls().
  std::vector<std::string> configures() const {
    std::vector<std::string> out;
    for (const std::string& call : calls())
      if (call.rfind("cmake --preset", 0) == 0) out.push_back(call);
    return out;
  }

  /// Writes an executable shell script at `path` (relative to the root).
  void executable(const std::string& path, const std::string& body) const {
    const std::string full = root_ + "/" + path;
    std::filesystem::create_directories(std::filesystem::path(full).parent_path());
    std::ofstream(full) << "#!/bin/sh\n" << body << "\n";
    std::filesystem::permissions(full, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add);
  }

  const std::string& root() const { return root_; }

 private:
  std::string root_;
};

}  // namespace bb::test
