// The claims ledger page: one row per claim, its text escaped once for Markdown.
#include "report/claims_page.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(ClaimsPage, AClaimsTextIsEscapedOnceAndItsRowNamesTheCase) {
  static Scene scene;
  scene = test::scene_from(test::minimal_case("spin") + R"(
[[claim]]
text = "the ball spins at |v| / r"
seed = "5. Rotations"
left = "reference:position_max"
op = "<"
right = 1.0
)");
  CaseResults results;
  results.scene = &scene;
  const std::string page = claims_page({results});
  EXPECT_NE(page.find("the ball spins at \\|v\\| / r"), std::string::npos) << page;
  EXPECT_EQ(page.find("\\\\"), std::string::npos) << page;
  EXPECT_NE(page.find("[spin](spin.md)"), std::string::npos);
  EXPECT_NE(page.find("1 claims"), std::string::npos);
}

}  // namespace
}  // namespace bb
