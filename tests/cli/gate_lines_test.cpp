// A gate says what it was measured against: on a case the reference cannot answer, `check`'s
// line, the JUnit test case and the page's gate table each say the value is against the
// backend's own finest run; a case with no gates says "no gates", never "all gates pass".
#include <gtest/gtest.h>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::beachball;

constexpr const char* kAgainst = "against its own run at the finest dt, not the reference";

TEST(GateLines, AGateOnTheFallbackSaysSoInCheckJUnitAndThePage) {
  const std::string dir = test::fresh_dir("gate_fallback");
  const std::string file =
      test::write_case(dir, "stack.toml",
                       std::string(test::kStackedBalls) +
                           "\n[[gate]]\nbackend = \"course/semi-implicit-euler\"\nmetric = "
                           "\"position_max\"\nmax = 100.0\n");
  const test::Outcome o = beachball("check " + file + " --junit " + dir + "/junit.xml --cache off");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find(kAgainst), std::string::npos) << o.out;
  EXPECT_NE(test::bytes(dir + "/junit.xml").find(kAgainst), std::string::npos);
  const test::Outcome run =
      beachball("run " + file + " --out " + dir + "/out --no-cost --cache off");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const std::string page = test::bytes(dir + "/out/stack.md");
  EXPECT_NE(page.substr(page.find("## Gates")).find(kAgainst), std::string::npos) << page;
}

TEST(GateLines, ACaseWithNoGatesSaysNoGates) {
  const std::string dir = test::fresh_dir("no_gates");
  const std::string file = test::write_case(dir, "plain.toml", test::minimal_case("plain"));
  const test::Outcome o = beachball("check " + file + " --cache off");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("plain: no gates"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("all gates pass"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nno gates\n"), std::string::npos) << o.out;
}

}  // namespace
}  // namespace bb
