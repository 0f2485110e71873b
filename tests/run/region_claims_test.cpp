// A map's claim ([[claim]] with `region`): its verdict counts the map's points as a count made
// by hand from the map's cells does (where the point's step lies against 2 / omega, with the
// margin, and whether the cell's outcome is the one claimed there); a claim whose region is
// wrong (its boundary at half the theory's) fails exactly where semi-implicit Euler is stable
// but the claim says it explodes; the picture crosses out those points; and a map's claim
// that cannot be judged is refused at load, at its line.
#include "run/region_claims.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report/json_writer.hpp"
#include "report/map_claim_picture.hpp"
#include "run/case_runner.hpp"
#include "run/claims.hpp"
#include "study/case_error.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Rows k = 2, 50, 100, 800 (omega 2, 10, 14.1, 40; 2 / omega 1, 0.2, 0.141, 0.05 s) by
/// steps 0.1, 0.04, 0.02, 0.01 s, and one map's claim on semi-implicit Euler: ok inside,
/// exploded outside, its boundary at `factor` times the theory's, margin 0.25.
std::string claimed_map(const std::string& factor) {
  return test::spring_map_case("claimed", "[2.0, 50.0, 100.0, 800.0]", "[0.1, 0.04, 0.02, 0.01]",
                               R"(["semi-implicit-euler"])") +
         R"([[claim]]
text = "Semi-implicit Euler is ok below the line and explodes above it"
own = true
region = "theory"
backend = "course/semi-implicit-euler"
margin = 0.25
boundary_factor = )" +
         factor + "\n";
}

CaseResults run_map(const Scene& scene) {
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.cost = false;
  options.jobs = 2;
  return run_case(scene, Registry::load(), options);
}

/// The counts made by hand from the map's cells: 2 / omega = 2 / sqrt(2 k) times `factor`,
/// the margin 0.25, each cell's outcome.
RegionCounts count_by_hand(const CaseResults& results, double factor) {
  RegionCounts n;
  for (const SweepPoint& p : results.sweep->points) {
    const double boundary = factor * 2.0 / std::sqrt(2.0 * p.value);
    const double dt = p.second_value;
    const bool inside = dt<0.75 * boundary, outside = dt> 1.25 * boundary;
    if (!inside && !outside) {
      ++n.within_margin;
      continue;
    }
    const RunRecord* run = nullptr;
    for (const RunRecord& r : p.runs)
      if (r.backend == "course/semi-implicit-euler") run = &r;
    const MapOutcome outcome = map_outcome(*results.scene, run);
    const bool exploded = outcome == MapOutcome::PastOnset || outcome == MapOutcome::Diverged;
    ++n.judged;
    const bool held = inside ? outcome == MapOutcome::Ok : exploded;
    n.held += held;
    if (!held) n.failing.emplace_back(p.value, p.second_value);
  }
  return n;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RegionClaims, TheVerdictCountsTheMapsCellsAsAHandCountDoes) {
  const Scene scene = test::scene_from(claimed_map("1.0"));
  const CaseResults results = run_map(scene);
  ASSERT_EQ(results.claims.size(), 1u);
  const ClaimVerdict& v = results.claims.front().verdicts.front();
  ASSERT_TRUE(v.region);
  const RegionCounts hand = count_by_hand(results, 1.0);
  EXPECT_EQ(v.region->judged, hand.judged);
  EXPECT_EQ(v.region->held, hand.held);
  EXPECT_EQ(v.region->within_margin, hand.within_margin);
  EXPECT_EQ(v.region->failing, hand.failing);
  EXPECT_EQ(v.region->no_outcome + v.region->unclaimed + v.region->no_theory, 0);
  // The map has both sides and the margin: 16 points, one (k = 800 at 0.04 s, 0.8 of the
  // line) within it; the theory holds at every other.
  EXPECT_EQ(hand.judged + hand.within_margin, 16);
  EXPECT_EQ(hand.within_margin, 1);
  EXPECT_EQ(hand.held, hand.judged);
  EXPECT_EQ(v.kind, VerdictKind::Holds);
  EXPECT_EQ(v.verdict,
            "holds at 15 of 15 judged points; not judged: 1 within 25 % of the boundary");
  // The results say the same.
  const auto points =
      results_json(results)["claims"][0]["verdicts"]["course/semi-implicit-euler"]["points"];
  EXPECT_EQ(points["judged"], hand.judged);
  EXPECT_EQ(points["within_margin"], 1);
  EXPECT_EQ(points["failing"].size(), 0u);
}

TEST(RegionClaims, AClaimWithItsBoundaryAtHalfTheTheorysFailsWhereTheMethodIsStable) {
  const Scene scene = test::scene_from(claimed_map("0.5"));
  const CaseResults results = run_map(scene);
  const ClaimVerdict& v = results.claims.front().verdicts.front();
  ASSERT_TRUE(v.region);
  const RegionCounts hand = count_by_hand(results, 0.5);
  EXPECT_EQ(v.region->judged, hand.judged);
  EXPECT_EQ(v.region->held, hand.held);
  EXPECT_EQ(v.region->within_margin, hand.within_margin);
  EXPECT_EQ(v.region->failing, hand.failing);
  // It says "exploded" between half the line and the line itself, where semi-implicit Euler
  // is stable: at k = 100, 0.1 s (0.71 of 2 / omega) and k = 800, 0.04 s (0.8 of it). Those,
  // and only those, fail.
  const std::vector<std::pair<double, double>> stable_but_claimed = {{100.0, 0.1}, {800.0, 0.04}};
  EXPECT_EQ(v.region->failing, stable_but_claimed);
  EXPECT_EQ(v.kind, VerdictKind::Partial);
  EXPECT_EQ(v.verdict,
            "holds at " + std::to_string(hand.held) + " of " + std::to_string(hand.judged) +
                " judged points, fails at 2; not judged: " + std::to_string(hand.within_margin) +
                " within 25 % of the boundary");
  EXPECT_EQ(claim_standing(results.claims.front()), ClaimStanding::Fails);
  // The picture crosses out the two (and the legend's swatch), rings those not judged.
  const std::string svg = map_claim_svg(results, results.claims.front());
  EXPECT_EQ(count_of(svg, "stroke=\"#000000\" stroke-width=\"2\"/>"), 2u + 1u);
  EXPECT_EQ(count_of(svg, "<circle"), static_cast<std::size_t>(hand.within_margin) + 1u);
  EXPECT_EQ(map_claim_file(scene, 0), "claimed-claim-1.svg");
}

TEST(RegionClaims, AMapsClaimThatCannotBeJudgedIsRefusedAtItsLine) {
  const std::string map = claimed_map("1.0");
  const auto refused = [](const std::string& text, const std::string& words) {
    try {
      test::scene_from(text);
      ADD_FAILURE() << "not refused: " << words;
    } catch (const CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
    }
  };
  // An engine: the course theory gives it no line.
  std::string engine = map;
  engine.replace(engine.find("course/semi-implicit-euler\""), 27, "ode\"");
  refused(engine, "for which no theory bounds 'spring.1.stiffness' or 'dt'");
  // A claim that compares quantities has no place in a map's claim.
  refused(map + "op = \">\"\n", "'op' belongs to a claim that compares two quantities");
  refused(map + "inside = \"stable\"\n", "known: ok, exploded");
  // Without a step axis no theory bounds the spring map.
  std::string no_step = map;
  no_step.replace(no_step.find("parameter = \"dt\""), 16, "parameter = \"spring.1.damping\"");
  no_step.replace(no_step.find("values = [0.1, 0.04, 0.02, 0.01]"), 32, "values = [0.0, 0.1]");
  refused(no_step, "no theory bounds 'spring.1.stiffness' or 'spring.1.damping'");
  // Without a map there is nothing to judge it over.
  std::string one_sweep = map;
  one_sweep.erase(one_sweep.find("[[sweep]]\nparameter = \"dt\""),
                  one_sweep.find("[[claim]]") - one_sweep.find("[[sweep]]\nparameter = \"dt\""));
  refused(one_sweep, "is judged over a map: the case needs two [[sweep]]s");
}

TEST(RegionClaims, WithoutTheMapTheClaimIsNotMeasured) {
  const Scene scene = test::scene_from(claimed_map("1.0"));
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.cost = false;
  options.sweep = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  const ClaimVerdict& v = results.claims.front().verdicts.front();
  EXPECT_EQ(v.kind, VerdictKind::NotMeasured);
  EXPECT_EQ(v.verdict, "not measured (the map did not run)");
  EXPECT_EQ(claim_standing(results.claims.front()), ClaimStanding::Neither);
}

}  // namespace
}  // namespace bb
