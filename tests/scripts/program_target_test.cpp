// The `program` target (what scripts/report builds) is the program and every engine plugin:
// no test program, no benchmark, nothing compiled from tests/ or bench/.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

TEST(ProgramTarget, BuildsTheProgramAndItsPluginsAndNoTestOrBenchmark) {
  const std::string build = BEACHBALL_BUILD_DIR;
  if (!fs::exists(build + "/build.ninja"))
    GTEST_SKIP() << "this build was not made by Ninja (every preset uses it)";
  // Every command that builds `program` from nothing, whatever is built already.
  const test::Outcome o = test::shell("ninja -C " + build + " -t commands program");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  std::istringstream lines(o.out);
  int compiled = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find(" -c ") == std::string::npos) continue;
    ++compiled;
    EXPECT_EQ(line.find(test::source_path("tests/")), std::string::npos) << line;
    EXPECT_EQ(line.find(test::source_path("bench/")), std::string::npos) << line;
  }
  EXPECT_GT(compiled, 0);
  EXPECT_NE(o.out.find("-o bin/beachball "), std::string::npos);
  // Each plugin this build has, among what the target links.
  int plugins = 0;
  for (const auto& entry : fs::directory_iterator(build + "/bin/plugins")) {
    const std::string file = "bin/plugins/" + entry.path().filename().string();
    EXPECT_NE(o.out.find("-o " + file), std::string::npos) << file;
    ++plugins;
  }
  EXPECT_GT(plugins, 0);
}

}  // namespace
}  // namespace bb
