// A map's claim judged on an axis other than the step: on a small friction map (the ground's
// tilt by its static friction), "the block holds below atan(mu_s) and slides above it" for the
// course's clamp friction is judged against the tilt's bound at each static friction, the
// line the map draws: its counts are a hand count's from the map's cells, with the tilt up the
// side or along the bottom; a boundary moved by boundary_factor moves points across it, and
// the count with them; and a claim on a map no theory bounds, or on a backend no theory
// covers there, is refused at its line, naming what the theories cover.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "run/case_runner.hpp"
#include "run/map_theory.hpp"
#include "run/region_claims.hpp"
#include "study/case_error.hpp"
#include "support/block_on_ground_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

constexpr const char* kCourse = "course/semi-implicit-euler";

/// A unit cube at rest on the ground (mu_k = 0.25), tilted 10 to 40 degrees, at static
/// frictions 0.3 and 0.6 (atan: 16.7 and 31.0 degrees); sliding is a final speed above
/// 0.01 m/s, the first [[sweep]]'s onset. `tilt_first`: the tilt up the side, else along the
/// bottom. One map's claim on the course's clamp friction: ok inside, exploded (slides)
/// outside, margin 0.05, its boundary at `factor` times atan(mu_s).
std::string friction_map(bool tilt_first, const std::string& factor) {
  const std::string tilts = R"([[sweep]]
parameter = "ground.normal"
values = [10.0, 20.0, 26.0, 40.0]
)";
  const std::string frictions = R"([[sweep]]
parameter = "ground.friction_static"
values = [0.3, 0.6]
)";
  const std::string onset = "onset = \"final_velocity/block\"\nonset_above = 0.01\n";
  return test::block_on_ground_case("friction_claim",
                                    "ground = [\"clamp\"]\nfriction = [\"clamp\"]\n") +
         (tilt_first ? tilts + onset + frictions : frictions + onset + tilts) +
         R"([[claim]]
text = "The block holds below atan(mu_s) and slides above it"
own = true
region = "theory"
backend = "course/semi-implicit-euler"
margin = 0.05
boundary_factor = )" +
         factor + "\n";
}

CaseResults run_map(const Scene& scene) {
  RunOptions options;
  options.backends = {kCourse};
  options.cost = false;
  options.jobs = 2;
  return run_case(scene, Registry::load(), options);
}

/// The counts made by hand from the map's cells: the boundary `factor` atan(mu_s) in degrees
/// at each point's static friction, the margin 0.05, each cell's outcome (sliding: past the
/// onset, or diverged).
RegionCounts count_by_hand(const CaseResults& results, bool tilt_first, double factor) {
  RegionCounts n;
  for (const SweepPoint& p : results.sweep->points) {
    const double tilt = tilt_first ? p.value : p.second_value;
    const double mu = tilt_first ? p.second_value : p.value;
    const double boundary = factor * std::atan(mu) * 180.0 / std::numbers::pi;
    const bool inside = tilt<0.95 * boundary, outside = tilt> 1.05 * boundary;
    if (!inside && !outside) {
      ++n.within_margin;
      continue;
    }
    const RunRecord* run = nullptr;
    for (const RunRecord& r : p.runs)
      if (r.backend == kCourse) run = &r;
    const MapOutcome outcome = map_outcome(*results.scene, run);
    const bool slid = outcome == MapOutcome::PastOnset || outcome == MapOutcome::Diverged;
    ++n.judged;
    const bool held = inside ? outcome == MapOutcome::Ok : slid;
    n.held += held;
    if (!held) n.failing.emplace_back(p.value, p.second_value);
  }
  return n;
}

TEST(RegionClaimAxes, AClaimOnTheTiltIsJudgedAgainstAtanMuSOnEitherAxis) {
  for (const bool tilt_first : {true, false}) {
    const Scene scene = test::scene_from(friction_map(tilt_first, "1.0"));
    ASSERT_NE(map_theory(scene, kCourse), nullptr);
    EXPECT_EQ(map_theory(scene, kCourse)->bounded, "ground.normal");
    const CaseResults results = run_map(scene);
    const ClaimVerdict& v = results.claims.front().verdicts.front();
    ASSERT_TRUE(v.region) << v.verdict;
    const RegionCounts hand = count_by_hand(results, tilt_first, 1.0);
    EXPECT_EQ(v.region->judged, hand.judged) << tilt_first;
    EXPECT_EQ(v.region->held, hand.held) << tilt_first;
    EXPECT_EQ(v.region->within_margin, hand.within_margin) << tilt_first;
    EXPECT_EQ(v.region->failing, hand.failing) << tilt_first;
    EXPECT_EQ(v.region->no_theory + v.region->no_outcome + v.region->unclaimed, 0) << tilt_first;
    // Every point is at least 6 % from its line: all 8 judged, and the course's clamp rule
    // holds the block below atan(mu_s) and lets it slide above, as Coulomb's law does.
    EXPECT_EQ(hand.judged, 8);
    EXPECT_EQ(hand.held, 8);
    EXPECT_EQ(v.kind, VerdictKind::Holds) << v.verdict;
    // The region's boundary at each point is the line the map draws there.
    const std::vector<RegionPoint> points = region_points(results, *results.claims.front().claim);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const SweepPoint& p = results.sweep->points[i];
      const double mu = tilt_first ? p.second_value : p.value;
      ASSERT_TRUE(points[i].boundary);
      EXPECT_NEAR(*points[i].boundary, std::atan(mu) * 180.0 / std::numbers::pi, 1e-12);
    }
  }
}

TEST(RegionClaimAxes, ABoundaryMovedByItsFactorMovesTheCount) {
  const Scene scene = test::scene_from(friction_map(true, "0.7"));
  const CaseResults results = run_map(scene);
  const ClaimVerdict& v = results.claims.front().verdicts.front();
  ASSERT_TRUE(v.region) << v.verdict;
  const RegionCounts hand = count_by_hand(results, true, 0.7);
  EXPECT_EQ(v.region->judged, hand.judged);
  EXPECT_EQ(v.region->held, hand.held);
  EXPECT_EQ(v.region->within_margin, hand.within_margin);
  EXPECT_EQ(v.region->failing, hand.failing);
  // At 0.7 atan(0.6) = 21.7 degrees the line passes below 26 degrees, where the block holds
  // (below 31.0): that point, and only that one, now says "slides" and fails.
  const std::vector<std::pair<double, double>> held_but_claimed = {{26.0, 0.6}};
  EXPECT_EQ(v.region->failing, held_but_claimed);
  EXPECT_EQ(v.kind, VerdictKind::Partial) << v.verdict;
}

/// Whether loading `text` is refused with a message holding each of `words`, at a line.
void expect_refused(const std::string& text, const std::vector<std::string>& words) {
  try {
    test::scene_from(text);
    ADD_FAILURE() << "not refused";
  } catch (const CaseError& e) {
    for (const std::string& w : words)
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
    EXPECT_GT(e.line(), 0) << e.what();
  }
}

TEST(RegionClaimAxes, AClaimNoTheoryBoundsIsRefusedNamingWhatTheTheoriesCover) {
  // The friction map without its tilt axis: static friction by the step, which no theory
  // bounds for a block on a level ground.
  std::string level = friction_map(true, "1.0");
  level.replace(level.find("parameter = \"ground.normal\""), 27, "parameter = \"dt\"");
  level.replace(level.find("values = [10.0, 20.0, 26.0, 40.0]"), 33, "values = [0.1, 0.05]");
  expect_refused(level, {"names backend 'course/semi-implicit-euler', for which no theory bounds "
                         "'dt' or 'ground.friction_static'",
                         "the ground's tilt (ground.normal)", "the step (dt)"});
}

}  // namespace
}  // namespace bb
