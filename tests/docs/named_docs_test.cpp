// What the program says to its users names only documents the repository has: the design a
// message or a page refers to is docs/design.md, not a DESIGN.md readers cannot find.
#include <gtest/gtest.h>

#include "study/case_error.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(NamedDocs, TheRefusalOfAnOldStabilityKeyNamesDocsDesign) {
  try {
    load_case(test::source_path("tests/bad_cases/stability_energy_factor_gone.toml"));
    FAIL() << "loaded without complaint";
  } catch (const CaseError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find("DESIGN.md"), std::string::npos) << message;
    EXPECT_NE(message.find("docs/design.md"), std::string::npos) << message;
  }
}

// A case the reference cannot answer (two balls stacked at the start): its page says what
// the errors are measured against and where the fallback is described.
TEST(NamedDocs, APageInTheFallbackNamesDocsDesign) {
  const std::string dir = test::fresh_dir("named_docs_fallback");
  const std::string path = test::write_case(dir, "stack.toml", test::kStackedBalls);
  const test::Outcome o = test::beachball(
      "run " + path + " --no-cost --backends course/semi-implicit-euler --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string page = test::bytes(dir + "/out/stack.md");
  ASSERT_NE(page.find("finest dt"), std::string::npos) << page;
  EXPECT_EQ(page.find("DESIGN.md"), std::string::npos);
  EXPECT_NE(page.find("docs/design.md"), std::string::npos);
}

}  // namespace
}  // namespace bb
