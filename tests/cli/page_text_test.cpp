// A title, a course section and a quote holding `< > & \ $ |` are rendered once on every page
// of a report: escaped for Markdown a single time (no "&amp;lt;", no doubled backslash, no
// math from a '$'), wherever they appear.
#include <gtest/gtest.h>

#include <filesystem>

#include "report/markdown_text.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTitle = R"(tan 28 < mu_s > 0 & a \ b $x$ | c)";
constexpr const char* kQuote = R"(Try $\epsilon$ < 1 & > 0 | here \ there)";

std::string hostile_case() {
  std::string text = test::minimal_case("hostile");
  text.replace(text.find("dims = 2"), 8,
               std::string("title = '") + kTitle + "'\nseed = '3. Projectiles'\ndims = 2");
  return text +
         "\n[[observe]]\nkind = \"max_speed\"\nbody = \"ball\"\n\n[[claim]]\n"
         "text = '" +
         kTitle + "'\nseed = '3. Projectiles'\nquote = '" + kQuote +
         "'\nleft = \"*:max_speed/ball\"\nop = \"<\"\nright = 100.0\n";
}

TEST(PageText, EveryPageRendersHostileTextOnceEscaped) {
  const std::string dir = test::fresh_dir("page_text");
  const std::string out = dir + "/out";
  test::write_case(dir + "/cases", "hostile.toml", hostile_case());
  const test::Outcome o =
      test::beachball("report " + dir + "/cases --out " + out + " --no-cost --cache off");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  int pages_with_title = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    if (entry.path().extension() != ".md") continue;
    const std::string page = test::bytes(entry.path());
    const std::string name = entry.path().filename().string();
    // Escaped twice would read "&amp;lt;" or four backslashes; a bare '$' would start math.
    for (const char* twice : {"&amp;lt;", "&amp;gt;", "&amp;amp;", "\\\\\\\\", "\\\\$"})
      EXPECT_EQ(page.find(twice), std::string::npos) << name << " holds " << twice;
    if (page.find(markdown_text(kTitle)) != std::string::npos) ++pages_with_title;
    if (name == "claims.md") {
      EXPECT_NE(page.find(markdown_text(kQuote)), std::string::npos) << page;
    }
  }
  // The index, the case's page and the claims ledger each show the title.
  EXPECT_GE(pages_with_title, 3);
  EXPECT_NE(markdown_text(kTitle).find("\\$x\\$"), std::string::npos);
}

}  // namespace
}  // namespace bb
