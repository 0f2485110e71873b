// A test the README promises, whose package is missing, skips on a user's machine and fails
// in CI (BEACHBALL_REQUIRE_ALL): shown with gnuplot out of reach (a PATH without it) for a
// test of the plots.
#include <gtest/gtest.h>

#include "support/program.hpp"

namespace bb {
namespace {

test::Outcome plots_test_without_gnuplot(const std::string& env) {
  return test::shell(env + " PATH=/nonexistent " + std::string(BEACHBALL_BUILD_DIR) +
                     "/bin/report_tests --gtest_filter=KeptDrawings.*");
}

TEST(RequireAll, AMissingPackageSkipsForAUserAndFailsInCi) {
  const test::Outcome user = plots_test_without_gnuplot("");
  EXPECT_EQ(user.exit_code, 0) << user.out;
  EXPECT_NE(user.out.find("[  SKIPPED ]"), std::string::npos) << user.out;
  EXPECT_NE(user.out.find("gnuplot is not installed"), std::string::npos) << user.out;
  const test::Outcome ci = plots_test_without_gnuplot("BEACHBALL_REQUIRE_ALL=1");
  EXPECT_NE(ci.exit_code, 0) << ci.out;
  EXPECT_NE(ci.out.find("[  FAILED  ]"), std::string::npos) << ci.out;
  EXPECT_NE(ci.out.find("gnuplot is not installed"), std::string::npos) << ci.out;
}

}  // namespace
}  // namespace bb
