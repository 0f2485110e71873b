// [[claim]]: a sentence checked by numbers. On a test-only case (a ball falling in drag,
// seen by two Euler integrators) a claim that holds and one that fails get those verdicts,
// "*" gives one verdict per backend, a claim whose truth depends on the step says from
// which dt it holds, and the run judges once into the results that the writers print.
// (Verdicts over made-up runs: claim_verdicts_test.cpp.)
#include "run/claims.hpp"

#include <gtest/gtest.h>

#include "report/claims_page.hpp"
#include "report/json_writer.hpp"
#include "report/table.hpp"
#include "study/case_error.hpp"
#include "support/claims_support.hpp"

namespace bb {
namespace {

using test::fall_case;
using test::judged;
using test::verdict;

TEST(Claims, AHoldingAndAFailingClaimGetTheirVerdictsWithTheirNumbers) {
  const CaseResults results = judged(R"(
[[claim]]
text = "the ball falls slower than it would in a vacuum"
own = true
left = "reference:final_speed/ball"
op = "<"
right = 19.62
[[claim]]
text = "explicit Euler is exact"
own = true
left = "course/explicit-euler:position_max"
op = "<"
right = 1e-9
)");
  const std::vector<ClaimResult> claims = judge_claims(results);
  ASSERT_EQ(claims.size(), 2u);
  ASSERT_EQ(claims[0].verdicts.size(), 1u);
  EXPECT_EQ(claims[0].verdicts[0].verdict, "holds");
  EXPECT_LT(*claims[0].verdicts[0].left, 19.62);
  EXPECT_EQ(*claims[0].verdicts[0].right, 19.62);
  EXPECT_EQ(verdict(claims[1], "course/explicit-euler").verdict, "fails");
  EXPECT_GT(*verdict(claims[1], "course/explicit-euler").left, 1e-9);
}

TEST(Claims, AStarGivesOneVerdictPerBackendAndAStepLimitWhereTheTruthDependsOnIt) {
  // First a run to place the limit between the errors at two steps.
  const CaseResults first = judged("");
  double at_coarse = 0.0, at_fine = 0.0;
  for (const RunRecord& run : first.runs)
    if (run.backend == "course/explicit-euler") {
      if (*run.dt == 0.05) at_coarse = run.errors->position_max;
      if (*run.dt == 0.025) at_fine = run.errors->position_max;
    }
  ASSERT_GT(at_coarse, at_fine);
  const double limit = 0.5 * (at_coarse + at_fine);
  const CaseResults results = judged(R"(
[[claim]]
text = "the error is small"
own = true
left = "*:position_max"
op = "<="
right = )" + std::to_string(limit) + R"(
[[claim]]
text = "every method agrees with the reference on the final speed"
own = true
left = "*:final_speed/ball"
op = "~"
right = "reference:final_speed/ball"
tolerance = 1.0
)");
  const std::vector<ClaimResult> claims = judge_claims(results);
  // One verdict each for the two integrators: a comparison with the reference is none for
  // the reference itself.
  ASSERT_EQ(claims[1].verdicts.size(), 2u);
  EXPECT_THROW(verdict(claims[1], "reference"), std::runtime_error);
  // The reference has no error against itself: it is not judged on one.
  ASSERT_EQ(claims[0].verdicts.size(), 2u);
  EXPECT_THROW(verdict(claims[0], "reference"), std::runtime_error);
  EXPECT_EQ(verdict(claims[0], "course/explicit-euler").verdict, "holds for dt <= 1/40 s");
  EXPECT_EQ(verdict(claims[1], "course/semi-implicit-euler").verdict, "holds");
}

TEST(Claims, AClaimNamingAMissingQuantityIsALoadErrorWithItsLine) {
  try {
    test::scene_from(fall_case() + R"(
[[claim]]
text = "the elephant falls faster"
own = true
left = "reference:final_speed/elephant"
op = ">"
right = 1.0
)");
    FAIL() << "loaded";
  } catch (const CaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("inline.toml:"), std::string::npos) << what;
    EXPECT_NE(what.find("final_speed/elephant"), std::string::npos) << what;
  }
}

// Verdicts are judged once, by the run, into the results; the JSON and the pages print
// what the results hold rather than judging again.
TEST(Claims, TheRunJudgesOnceIntoTheResultsAndTheWritersPrintThoseVerdicts) {
  CaseResults results = judged(R"(
[[claim]]
text = "the ball falls slower than it would in a vacuum"
own = true
left = "reference:final_speed/ball"
op = "<"
right = 19.62
)");
  ASSERT_EQ(results.claims.size(), 1u);
  ASSERT_EQ(results.claims[0].verdicts.size(), 1u);
  EXPECT_EQ(results.claims[0].verdicts[0].verdict, "holds");
  EXPECT_EQ(results.claims[0].claim, &results.scene->claims[0]);
  results.claims[0].verdicts[0].verdict = "as the results say";
  EXPECT_EQ(results_json(results)["claims"][0]["verdicts"]["reference"]["verdict"],
            "as the results say");
  EXPECT_NE(render_markdown(case_claims_table(results)).find("as the results say"),
            std::string::npos);
}

}  // namespace
}  // namespace bb
