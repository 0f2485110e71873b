// How a claim's verdict reads over a sweep's steps, on results made up for it: the step
// from which it holds, the steps it could not judge, a divergence as evidence where the claim
// says so, a comparison of errors, a backend that could not run, the ledger's standing, and
// an engine's one friction coefficient named as the cause of a failure on a slope.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "run/claims.hpp"
#include "support/claims_support.hpp"

namespace bb {
namespace {

using test::fall_case;
using test::made_up;
using test::verdict;

TEST(Claims, ARunThatDivergedIsNamedInTheVerdictNotSkipped) {
  static Scene scene;
  scene = test::scene_from(fall_case() + R"(
[[claim]]
text = "explicit Euler stays close"
own = true
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

// A claim that something goes wrong at a game's step holds at the large steps and fails at
// the small ones: the verdict names the step from which it holds, upwards.
TEST(Claims, AClaimTrueAtTheLargeStepsOnlySaysFromWhichStepUp) {
  static Scene scene;
  scene = test::scene_from(fall_case() + R"(
[[claim]]
text = "explicit Euler gains speed"
own = true
left = "course/explicit-euler:final_speed/ball"
op = ">"
right = 5.0
)");
  const CaseResults results = made_up(scene, "course/explicit-euler", {9.0, 7.0, 4.0, 3.0}, 3.0);
  const ClaimVerdict v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.verdict, "holds for dt >= 1/20 s");
  EXPECT_EQ(v.kind, VerdictKind::Partial);
}

// A verdict from some dts names those it could not judge: runs whose value is a note (a hit
// the backend resolved by pushing the bodies apart: "not measured: ..."), not a number. The
// ledger counts it apart from a claim that holds everywhere.
TEST(Claims, AVerdictNamesTheStepsItCouldNotJudge) {
  static Scene scene;
  scene = test::scene_from(fall_case() + R"(
[[claim]]
text = "explicit Euler keeps the speed"
own = true
left = "course/explicit-euler:final_speed/ball"
op = "~"
right = 3.0
tolerance = 0.5
)");
  CaseResults results = made_up(scene, "course/explicit-euler", {9.0, 7.0, 4.0, 3.0}, 3.0);
  for (RunRecord& run : results.runs)
    if (*run.dt < 0.03) run.observables[0].measured = {std::nullopt, "not measured: pushed apart"};
  ClaimResult claim = judge_claims(results)[0];
  EXPECT_EQ(claim.verdicts[0].verdict, "fails; not measured at dt 1/40, 1/80 s");
  EXPECT_EQ(claim.verdicts[0].kind, VerdictKind::Fails);
  // Holding where it was judged, it is not a claim that holds at every dt.
  for (RunRecord& run : results.runs)
    if (*run.dt > 0.03) run.observables[0].measured.value = 3.0;
  claim = judge_claims(results)[0];
  EXPECT_EQ(claim.verdicts[0].verdict, "holds; not measured at dt 1/40, 1/80 s");
  EXPECT_EQ(claim_standing(claim), ClaimStanding::Neither);
}

// `diverged = "holds"`: a run that blew up is evidence for a claim that something explodes;
// a backend that diverges at every step holds it instead of going unmeasured. `"fails"`:
// evidence against a claim that something stays bounded.
TEST(Claims, ADivergenceCountsWhereTheClaimSaysWhatItMeans) {
  static Scene scene;
  const std::string claim = R"(
[[claim]]
text = "a high spring constant explodes"
quote = "a high spring constant will cause the system to explode very quickly"
left = "course/explicit-euler:final_speed/ball"
op = ">"
right = 100.0
)";
  scene = test::scene_from(fall_case() + claim + "diverged = \"holds\"\n");
  const std::vector<std::optional<double>> all_diverged(4, std::nullopt);
  ClaimVerdict v =
      judge_claims(made_up(scene, "course/explicit-euler", all_diverged, 3.0))[0].verdicts[0];
  EXPECT_EQ(v.verdict, "holds; diverged at dt 1/10, 1/20, 1/40, 1/80 s, counted as holding");
  EXPECT_EQ(v.kind, VerdictKind::Holds);
  // Diverged at the two large steps, bounded below: it explodes at the large steps only.
  v = judge_claims(
          made_up(scene, "course/explicit-euler", {std::nullopt, std::nullopt, 4.0, 3.0}, 3.0))[0]
          .verdicts[0];
  EXPECT_EQ(v.verdict, "holds for dt >= 1/20 s; diverged at dt 1/10, 1/20 s, counted as holding");
  scene = test::scene_from(fall_case() + claim + "diverged = \"fails\"\n");
  v = judge_claims(
          made_up(scene, "course/explicit-euler", {std::nullopt, 200.0, 200.0, 200.0}, 3.0))[0]
          .verdicts[0];
  EXPECT_EQ(v.verdict, "holds for dt <= 1/20 s; diverged at dt 1/10 s, counted as failing");
}

// compare = "error": each side is its distance from the reference, so an overshoot does not
// pass for "better" (three_beachballs_1a's mirror against reflect).
TEST(Claims, CompareErrorReadsEachSideAsItsDistanceFromTheReference) {
  static Scene scene;
  const std::string claim = R"(
[[claim]]
text = "semi-implicit Euler is nearer the reference than explicit Euler"
own = true
left = "course/semi-implicit-euler:final_speed/ball"
op = "<"
right = "course/explicit-euler:final_speed/ball"
)";
  scene = test::scene_from(fall_case() + claim);
  // The reference says 5; semi-implicit overshoots to 9, explicit undershoots to 4.
  CaseResults results = made_up(scene, "course/explicit-euler", {4.0, 4.0, 4.0, 4.0}, 5.0);
  const CaseResults semi = made_up(scene, "course/semi-implicit-euler", {9.0, 9.0, 9.0, 9.0}, 5.0);
  results.runs.insert(results.runs.end(), semi.runs.begin(), semi.runs.end());
  // As values, 9 < 4 fails anyway; the point is the reading, checked both ways below.
  scene = test::scene_from(fall_case() + claim + "compare = \"error\"\n");
  ClaimVerdict v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.verdict, "fails");
  EXPECT_EQ(*v.left, 4.0);
  EXPECT_EQ(*v.right, 1.0);
  for (RunRecord& run : results.runs)
    if (run.backend == "course/semi-implicit-euler") run.observables[0].measured.value = 5.5;
  v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.verdict, "holds");
  EXPECT_EQ(*v.left, 0.5);
}

// A claim counts in the ledger's headline as failing only where a backend fails or holds in
// part; one whose runs diverged without bearing on it, or could not be measured, is neither.
TEST(Claims, StandingCountsOnlyFailuresAndPartialHoldsAsFailing) {
  ClaimResult c;
  const auto verdict = [](const char* backend, const char* text, VerdictKind kind) {
    ClaimVerdict v;
    v.backend = backend, v.verdict = text, v.kind = kind;
    return v;
  };
  const ClaimVerdict holds = verdict("a", "holds", VerdictKind::Holds);
  ClaimVerdict diverged = verdict("b", "holds; diverged at dt 1/30 s", VerdictKind::Holds);
  diverged.diverged = {1.0 / 30};
  ClaimVerdict counted = diverged;
  counted.diverged_judged = true;
  const ClaimVerdict unmeasured =
      verdict("c", "not measured (c has no value for it)", VerdictKind::NotMeasured);
  const ClaimVerdict partial = verdict("d", "holds for dt <= 1/60 s", VerdictKind::Partial);
  c.verdicts = {holds, counted};
  EXPECT_EQ(claim_standing(c), ClaimStanding::Holds);
  c.verdicts = {holds, diverged};
  EXPECT_EQ(claim_standing(c), ClaimStanding::Neither);
  c.verdicts = {holds, unmeasured};
  EXPECT_EQ(claim_standing(c), ClaimStanding::Neither);
  c.verdicts = {unmeasured, partial};
  EXPECT_EQ(claim_standing(c), ClaimStanding::Fails);
}

// An engine given one friction coefficient (mu_k) on a slope between atan(mu_k) and
// atan(mu_s) lets a block slide that Coulomb holds: its failing verdict says so, with the
// angles computed from the case; on level ground there is no such cause.
TEST(Claims, AnEnginesOneFrictionCoefficientIsNamedAsTheCauseOnASlopeItCannotHold) {
  const std::string slope = R"(name = "slope"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1]
report_dt = 0.1
[ground]
normal = [0.4694715627858908, 0.882947592858927, 0.0]
friction_static = 0.6
friction_kinetic = 0.5
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [0.2347357813929454, 0.4414737964294635, 0.0]
angle = -28.0
[[observe]]
kind = "rest_creep"
body = "block"
[[claim]]
text = "static friction holds it"
quote = "up to a maximum"
left = "*:rest_creep/block"
op = "<"
right = 0.001
)";
  static Scene scene;
  scene = test::scene_from(slope);
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  results.reference_run.observables = {{"rest_creep/block", {0.0, ""}, 0.0}};
  RunRecord engine;
  engine.backend = "box2d";
  engine.dt = 0.1;
  engine.observables = {{"rest_creep/block", {1.24, ""}, 0.0}};
  engine.engine_settings = {{"friction_rule", std::string("one coefficient")},
                            {"ground_friction_min", 0.5},
                            {"ground_friction_max", 0.5}};
  results.runs.push_back(engine);
  std::vector<ClaimResult> claims = judge_claims(results);
  EXPECT_EQ(verdict(claims[0], "reference").cause, "");
  const ClaimVerdict& v = verdict(claims[0], "box2d");
  EXPECT_EQ(v.verdict, "fails");
  EXPECT_NE(v.cause.find("given mu_k = 0.5"), std::string::npos) << v.cause;
  EXPECT_NE(v.cause.find("26.57 degrees"), std::string::npos) << v.cause;
  EXPECT_NE(v.cause.find("slopes at 28.00 degrees"), std::string::npos) << v.cause;
  EXPECT_NE(v.cause.find("30.96"), std::string::npos) << v.cause;
  // Level ground: the engine's coefficient decides nothing a static claim depends on.
  std::string level = slope;
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"normal = [0.4694715627858908, 0.882947592858927, 0.0]",
                                            "normal = [0.0, 1.0, 0.0]"},
        {"[0.2347357813929454, 0.4414737964294635, 0.0]", "[0.0, 0.5, 0.0]"},
        {"angle = -28.0", "angle = 0.0"}})
    level.replace(level.find(from), from.size(), to);
  scene = test::scene_from(level);
  claims = judge_claims(results);
  EXPECT_EQ(verdict(claims[0], "box2d").cause, "");
}

// A backend that cannot run the case is not measured, and its verdict says why: the run's
// reason, the features it lacks.
TEST(Claims, ABackendThatCannotRunTheCaseSaysWhyItIsNotMeasured) {
  static Scene scene;
  scene = test::scene_from(fall_case() + R"(
[[claim]]
text = "every backend's ball ends below 10 m/s"
own = true
left = "*:final_speed/ball"
op = "<"
right = 10.0
)");
  CaseResults results = made_up(scene, "course/explicit-euler", {9.0, 7.0, 4.0, 3.0}, 3.0);
  RunRecord lacking;
  lacking.backend = "engine-without-drag";
  lacking.dt = scene.report_dt;
  lacking.status = RunStatus::Unsupported;
  lacking.reason = "does not support: drag";
  results.runs.push_back(lacking);
  const ClaimResult claim = judge_claims(results)[0];
  const ClaimVerdict& v = verdict(claim, "engine-without-drag");
  EXPECT_EQ(v.kind, VerdictKind::NotMeasured);
  EXPECT_EQ(v.verdict, "not measured (unsupported: does not support: drag)");
  EXPECT_EQ(verdict(claim, "course/explicit-euler").kind, VerdictKind::Holds);
}

}  // namespace
}  // namespace bb
