// [[claim]]: a sentence checked by numbers. On a test-only case (a ball falling in drag,
// seen by two Euler integrators) a claim that holds and one that fails get those verdicts,
// "*" gives one verdict per backend, and a claim whose truth depends on the step says from
// which dt it holds.
#include "run/claims.hpp"

#include <gtest/gtest.h>

#include "report/claims_page.hpp"
#include "report/json_writer.hpp"
#include "report/table.hpp"
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

/// Results of `backend` at the four steps of fall_case(), with `final_speed/ball` measured
/// as `values[i]` (nullopt: the run diverged) and the reference's as `reference`.
CaseResults made_up(const Scene& scene, const std::string& backend,
                    const std::vector<std::optional<double>>& values, double reference) {
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  results.reference_run.observables = {{"final_speed/ball", {reference, ""}, reference}};
  const std::vector<double> dts = {0.1, 0.05, 0.025, 0.0125};
  for (std::size_t i = 0; i < dts.size(); ++i) {
    RunRecord run;
    run.backend = backend;
    run.dt = dts[i];
    if (values[i]) {
      run.observables = {{"final_speed/ball", {*values[i], ""}, reference}};
    } else {
      run.status = RunStatus::Diverged;
    }
    results.runs.push_back(run);
  }
  return results;
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
