// .ci/run: the gates of the bundled suite run beside the tests, from the same build, with leak
// detection, starting once the program is built (beside the test programs' build too); CI
// fails when either fails and prints what the gates said.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/script_sandbox.hpp"

namespace bb {
namespace {

/// A sandbox holding .ci/run, where the tests (ctest) and the gates (the program's check) each
/// wait up to 5 s for the other to have started, and say whether it had.
test::ScriptSandbox ci_sandbox(const std::string& name) {
  test::ScriptSandbox box(name);
  std::filesystem::create_directories(box.root() + "/.ci");
  std::filesystem::copy_file(test::source_path(".ci/run"), box.root() + "/.ci/run");
  const std::string wait_for =
      "i=0; while [ ! -f \"$1\" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i+1)); done\n"
      "if [ -f \"$1\" ]; then echo beside; else echo alone; fi\n";
  box.executable("stand-ins/wait-for", wait_for);
  // A build of everything says whether the gates were running by then; the program's own
  // build, which they need, says nothing.
  box.executable("stand-ins/cmake",
                 "if [ \"$1\" = --preset ]; then\n"
                 "  echo \"cmake $*\" >> \"$CALLS\"\n"
                 "  mkdir -p build-asan; echo CMAKE_GENERATOR:INTERNAL=Ninja > "
                 "build-asan/CMakeCache.txt\n"
                 "elif [ \"$4\" = --target ]; then echo \"cmake $*\" >> \"$CALLS\"\n"
                 "else echo \"cmake $* $(wait-for gates-running)\" >> \"$CALLS\"; fi");
  box.executable("stand-ins/ctest",
                 "touch tests-running\n"
                 "echo \"ctest $* $(wait-for gates-running)\" >> \"$CALLS\"\n"
                 "exit ${TESTS_EXIT:-0}");
  box.executable("build-asan/bin/beachball",
                 "touch gates-running\n"
                 "echo \"beachball $* ASAN_OPTIONS=$ASAN_OPTIONS $(wait-for tests-running)\" "
                 ">> \"$CALLS\"\n"
                 "echo 'what the gates said'\n"
                 "exit ${GATES_EXIT:-0}");
  return box;
}

bool called(const std::vector<std::string>& calls, const std::string& line) {
  return std::find(calls.begin(), calls.end(), line) != calls.end();
}

TEST(CiScript, RunsTheGatesBesideTheTestsOnTheSanitizerBuild) {
  const test::ScriptSandbox box = ci_sandbox("ci_script");
  const test::Outcome o = box.run(".ci/run");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::vector<std::string> calls = box.calls();
  // The tests' packages and the sanitizer build's compiler (clang), before anything is built.
  ASSERT_FALSE(calls.empty()) << o.out;
  EXPECT_EQ(calls.front(), "setup --tests --sanitizers") << o.out;
  EXPECT_TRUE(called(calls, "ctest --preset asan beside")) << o.out;
  EXPECT_TRUE(called(calls,
                     "beachball check --timeout 600 --junit build-asan/gates.xml "
                     "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 beside"))
      << o.out;
  EXPECT_NE(o.out.find("what the gates said"), std::string::npos) << o.out;
  // The program first, alone; the rest of the build beside the gates.
  const auto program =
      std::find(calls.begin(), calls.end(), "cmake --build --preset asan --target program");
  const auto gates = std::find_if(calls.begin(), calls.end(), [](const std::string& c) {
    return c.rfind("beachball check", 0) == 0;
  });
  ASSERT_NE(program, calls.end()) << o.out;
  EXPECT_LT(program - calls.begin(), gates - calls.begin()) << o.out;
  EXPECT_TRUE(called(calls, "cmake --build --preset asan beside")) << o.out;
}

TEST(CiScript, FailsWhenTheTestsOrTheGatesFail) {
  for (const char* failing : {"TESTS_EXIT=1", "GATES_EXIT=1"}) {
    const test::ScriptSandbox box = ci_sandbox(std::string("ci_script_fail_") + failing[0]);
    const test::Outcome o = box.run(".ci/run", failing);
    EXPECT_NE(o.exit_code, 0) << failing << "\n" << o.out;
    // What the gates said is shown either way.
    EXPECT_NE(o.out.find("what the gates said"), std::string::npos) << failing << "\n" << o.out;
  }
}

}  // namespace
}  // namespace bb
