// What scripts/report and scripts/test build and run: the report only the program and its
// plugins (a newcomer's first report compiles no test), the tests with the preset asked
// for (CI runs the README's command on the sanitizer build), with what the preset's compiler
// needs installed.
#include <gtest/gtest.h>

#include "support/script_sandbox.hpp"

namespace bb {
namespace {

TEST(ReportScript, BuildsTheProgramTargetAlone) {
  const test::ScriptSandbox box("report_script");
  box.executable("build/bin/beachball", "echo \"beachball $*\" >> \"$CALLS\"");
  const test::Outcome o = box.run("scripts/report");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::vector<std::string> calls = box.calls();
  ASSERT_GE(calls.size(), 3u);
  EXPECT_EQ(calls.front(), "setup");
  EXPECT_EQ(calls[calls.size() - 2], "cmake --build --preset default --target program");
  EXPECT_EQ(calls.back(), "beachball report --out reports");
}

TEST(TestScript, RunsOnThePresetItIsGiven) {
  const test::ScriptSandbox box("test_script");
  const test::Outcome o = box.run("scripts/test -R Cli", "BEACHBALL_PRESET=asan");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::vector<std::string> calls = box.calls();
  ASSERT_EQ(calls.size(), 4u) << o.out;
  // The asan preset's compiler (clang) is installed with the tests' packages.
  EXPECT_EQ(calls[0], "setup --tests --sanitizers");
  EXPECT_EQ(calls[1], "cmake --preset asan");
  EXPECT_EQ(calls[2], "cmake --build --preset asan");
  EXPECT_EQ(calls[3], "ctest --preset asan -R Cli");
}

}  // namespace
}  // namespace bb
