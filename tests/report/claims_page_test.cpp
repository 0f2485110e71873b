// The claims ledger page: one row per claim, its text escaped once for Markdown.
#include "report/claims_page.hpp"

#include <gtest/gtest.h>

#include "report/markdown_writer.hpp"
#include "run/claims.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(ClaimsPage, AClaimsTextIsEscapedOnceAndItsRowNamesTheCase) {
  static Scene scene;
  scene = test::scene_from(test::minimal_case("spin") + R"(
[[claim]]
text = "the ball spins at |v| / r"
seed = "5. Rotations"
quote = "the rotation speed will be the same as the norm of the velocity over the radius"
left = "reference:position_max"
op = "<"
right = 1.0
)");
  CaseResults results;
  results.scene = &scene;
  results.claims = judge_claims(results);
  const std::string page = claims_page({results});
  EXPECT_NE(page.find("the ball spins at \\|v\\| / r"), std::string::npos) << page;
  EXPECT_EQ(page.find("\\\\"), std::string::npos) << page;
  EXPECT_NE(page.find("[spin](spin.md)"), std::string::npos);
  EXPECT_NE(page.find("1 claims"), std::string::npos);
}

/// A case with three claims on the final speed: the text's (quoted), the case's own, and
/// one whose only backend diverged at one step without bearing on it; judged on made-up
/// runs of explicit Euler (1/10 s diverged, 1/20 s measured) and the reference.
CaseResults three_claims(Scene& scene, double euler_speed) {
  scene = test::scene_from(test::minimal_case("fall") + R"(
[[observe]]
kind = "final_speed"
body = "ball"
[[claim]]
text = "the ball falls slower than in a vacuum"
seed = "8. Wind effects"
quote = "the drag varies linearly with area and by the square of the relative velocity"
left = "*:final_speed/ball"
op = "<"
right = 9.81
[[claim]]
text = "the ball is faster than 1 m/s"
own = true
left = "course/explicit-euler:final_speed/ball"
op = ">"
right = 1.0
[[claim]]
text = "explicit Euler agrees with the reference"
seed = "1. Movement in discrete time"
quote = "In the following, this primarily means that the time step"
left = "course/explicit-euler:position_max"
op = "<"
right = 1.0
)");
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  results.reference_run.observables = {{"final_speed/ball", {8.0, ""}, 8.0}};
  RunRecord diverged;
  diverged.backend = "course/explicit-euler";
  diverged.dt = 0.1;
  diverged.status = RunStatus::Diverged;
  results.runs.push_back(diverged);
  RunRecord run;
  run.backend = "course/explicit-euler";
  run.dt = 0.05;
  run.errors = ErrorMetrics{};
  run.errors->position_max = 0.5;
  run.observables = {{"final_speed/ball", {euler_speed, ""}, 8.0}};
  results.runs.push_back(run);
  results.claims = judge_claims(results);
  return results;
}

// The ledger quotes the course text's words with their section, marks a claim of the case's
// own as such, and does not count a "holds; diverged" or a reference that cannot have an
// error against itself as failing: they are counted apart.
TEST(ClaimsPage, QuotesMarksOwnClaimsAndCountsOnlyFailuresAsFailing) {
  static Scene scene;
  const std::string page = claims_page({three_claims(scene, 8.5)});
  EXPECT_NE(page.find("8. Wind effects: \"the drag varies linearly with area and by the square "
                      "of the relative velocity\""),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("the case's own claim, not the text's"), std::string::npos) << page;
  // Every verdict holds, though explicit Euler diverged at 1/10 s: nothing fails.
  EXPECT_NE(page.find("3 claims (2 from the course text, 1 the cases' own); 0 of them fail or "
                      "hold only in part for some backend"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("3 have a backend that diverged at some dt without bearing on the claim, "
                      "was capped, or could not be measured"),
            std::string::npos)
      << page;
  // Faster than a vacuum allows: the first claim fails for explicit Euler, and only it counts.
  const std::string failing = claims_page({three_claims(scene, 10.0)});
  EXPECT_NE(failing.find("1 of them fail or hold only in part"), std::string::npos) << failing;
  EXPECT_NE(failing.find("2 have a backend that diverged"), std::string::npos) << failing;
}

// A case's page shows its own claims: each sentence, the words quoted from the course text
// (or that it is the case's own), and every backend's verdict with its numbers.
TEST(ClaimsPage, TheCasePageShowsItsClaimsWithQuotesAndVerdicts) {
  static Scene scene;
  const std::string page = results_markdown(three_claims(scene, 10.0), PlotFiles{});
  const std::size_t section = page.find("## Claims");
  ASSERT_NE(section, std::string::npos) << page;
  const std::string claims = page.substr(section);
  EXPECT_NE(claims.find("the ball falls slower than in a vacuum"), std::string::npos) << claims;
  EXPECT_NE(claims.find("\"the drag varies linearly with area and by the square of the relative "
                        "velocity\""),
            std::string::npos)
      << claims;
  EXPECT_NE(claims.find("the case's own claim, not the text's"), std::string::npos) << claims;
  EXPECT_NE(claims.find("course/explicit-euler: **fails; diverged at dt 1/10 s** (10 &lt; 9.81)"),
            std::string::npos)
      << claims;
  EXPECT_NE(claims.find("reference: **holds** (8 &lt; 9.81)"), std::string::npos) << claims;
}

// Every case page has a Claims section: one whose case tests no claim says so in one line
// and links the ledger (the 18 bundled cases without claims had no section at all).
TEST(ClaimsPage, ACasePageWithoutClaimsSaysSoAndLinksTheLedger) {
  static Scene scene;
  scene = test::scene_from(test::minimal_case("quiet"));
  ASSERT_TRUE(scene.claims.empty());
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  const std::string page = results_markdown(results, PlotFiles{});
  const std::size_t section = page.find("\n## Claims\n\n");
  ASSERT_NE(section, std::string::npos) << page;
  const std::string body = page.substr(section + 12, page.find('\n', section + 12) - section - 12);
  EXPECT_NE(body.find("No claim of the course text is tested on this case"), std::string::npos)
      << body;
  EXPECT_NE(body.find("](claims.md)"), std::string::npos) << body;
  // One line, then the next section.
  EXPECT_EQ(page.compare(section + 12 + body.size(), 4, "\n\n##"), 0) << page.substr(section);
}

}  // namespace
}  // namespace bb
