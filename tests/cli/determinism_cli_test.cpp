// Bundled cases run twice, once with --jobs 1 and once with --jobs 2, write byte-identical
// JSON (cost is left out with --no-cost, as it is the one thing that may differ): the two
// runs differ both as two runs and in their jobs, so any difference of either kind shows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::string run_suite(const std::string& name, int jobs) {
  const std::string out = ::testing::TempDir() + "/determinism_" + name;
  fs::remove_all(out);
  // One case per kind of run: free flight, ground bounces with a collision, a stiff
  // reference (the short ones: a minute of bounces showed nothing more and took most of the
  // test's time).
  std::string cases;
  for (const char* c : {"drag_fall", "double_bounce", "tiny_mass_fall"})
    cases += test::source_path("cases/") + c + ".toml ";
  const std::string command = std::string(BEACHBALL_PROGRAM) + " run " + cases +
                              "--no-cost --jobs " + std::to_string(jobs) + " --out " + out +
                              " > /dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return out;
}

using test::bytes;

TEST(Determinism, SuiteJsonIsByteIdenticalAcrossRunsAndJobs) {
  const std::string first = run_suite("first", 1);
  const std::string parallel = run_suite("parallel", 2);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(first)) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(bytes(entry.path()), bytes(fs::path(parallel) / name)) << name;
    ++files;
  }
  EXPECT_GE(files, 3);
}

}  // namespace
}  // namespace bb
