// [[claim]]: a sentence checked by numbers. On a test-only case (a ball falling in drag,
// seen by two Euler integrators) a claim that holds and one that fails get those verdicts,
// "*" gives one verdict per backend, and a claim whose truth depends on the step says from
// which dt it holds.
#include "run/claims.hpp"

#include <gtest/gtest.h>

#include "run/case_runner.hpp"
#include "scene/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The minimal drag case over 2 s and a sweep of four steps, seen by two Euler integrators.
std::string fall_case() {
  std::string text = test::minimal_case("fall");
  const std::string old_time = "duration = 1.0\nsample = 0.1\ndt = [0.1, 0.05]\n";
  text.replace(text.find(old_time), old_time.size(),
               "duration = 2.0\nsample = 0.1\ndt = [0.1, 0.05, 0.025, 0.0125]\n");
  return text + R"(
[course]
integrators = ["explicit-euler", "semi-implicit-euler"]
[[observe]]
kind = "final_speed"
body = "ball"
)";
}

CaseResults judged(const std::string& claims) {
  static Scene scene;  // the results point into it
  scene = test::scene_from(fall_case() + claims);
  RunOptions options;
  options.backends = {"course/explicit-euler", "course/semi-implicit-euler"};
  options.cost = false;
  options.isolation = false;
  return run_case(scene, Registry::load(), options);
}

const ClaimVerdict& verdict(const ClaimResult& c, const std::string& backend) {
  for (const ClaimVerdict& v : c.verdicts)
    if (v.backend == backend) return v;
  throw std::runtime_error("no verdict for " + backend);
}

TEST(Claims, AHoldingAndAFailingClaimGetTheirVerdictsWithTheirNumbers) {
  const CaseResults results = judged(R"(
[[claim]]
text = "the ball falls slower than it would in a vacuum"
left = "reference:final_speed/ball"
op = "<"
right = 19.62
[[claim]]
text = "explicit Euler is exact"
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
left = "*:position_max"
op = "<="
right = )" + std::to_string(limit) + R"(
[[claim]]
text = "every method agrees with the reference on the final speed"
left = "*:final_speed/ball"
op = "~"
right = "reference:final_speed/ball"
tolerance = 1.0
)");
  const std::vector<ClaimResult> claims = judge_claims(results);
  // One verdict each for the reference and the two integrators.
  ASSERT_EQ(claims[0].verdicts.size(), 3u);
  // The reference has no error against itself: not a number to judge.
  EXPECT_EQ(verdict(claims[0], "reference").verdict.rfind("not measured", 0), 0u);
  EXPECT_EQ(verdict(claims[0], "course/explicit-euler").verdict, "holds for dt <= 1/40 s");
  EXPECT_EQ(verdict(claims[1], "course/semi-implicit-euler").verdict, "holds");
}

TEST(Claims, ARunThatDivergedIsNamedInTheVerdictNotSkipped) {
  static Scene scene;
  scene = test::scene_from(fall_case() + R"(
[[claim]]
text = "explicit Euler stays close"
left = "course/explicit-euler:position_max"
op = "<"
right = 0.5
)");
  CaseResults results;
  results.scene = &scene;
  // Blown up at the two large steps, measured (and close) at the two small ones.
  for (double dt : {0.1, 0.05, 0.025, 0.0125}) {
    RunRecord run;
    run.backend = "course/explicit-euler";
    run.dt = dt;
    if (dt > 0.03) {
      run.status = RunStatus::Diverged;
    } else {
      run.errors = ErrorMetrics{};
      run.errors->position_max = 0.1;
    }
    results.runs.push_back(run);
  }
  ClaimVerdict v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.verdict, "holds; diverged at dt 1/10, 1/20 s");
  // Blown up everywhere: nothing to judge, and the verdict says why.
  for (RunRecord& run : results.runs) run.status = RunStatus::Diverged;
  v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.verdict, "not measured (diverged at dt 1/10, 1/20, 1/40, 1/80 s)");
}

TEST(Claims, AClaimNamingAMissingQuantityIsALoadErrorWithItsLine) {
  try {
    test::scene_from(fall_case() + R"(
[[claim]]
text = "the elephant falls faster"
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

}  // namespace
}  // namespace bb
