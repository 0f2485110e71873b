// A map's estimate from its first point: that point's time outside its runs' steps once per
// other point, its steps' time in proportion to each point's steps, over the jobs; and the
// point that runs first is the one with the most steps (a step axis's smallest step).
#include "run/map_budget.hpp"

#include <gtest/gtest.h>

#include "run/sweep_runner.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(MapBudget, TheEstimateScalesTheFirstPointsStepsByEachPointsSteps) {
  const Scene scene = test::scene_from(test::spring_map_case(
      "estimate", "[2.0, 50.0]", "[0.1, 0.01, 0.001]", R"(["semi-implicit-euler"])"));
  std::vector<SweepPoint> points = sweep_points(scene);  // (2, 0.1), (2, 0.01), (2, 0.001), ...
  ASSERT_EQ(points.size(), 6u);
  // Over 1 s: 10, 100 and 1000 steps a run.
  EXPECT_DOUBLE_EQ(point_steps(scene, points[0]), 10.0);
  EXPECT_DOUBLE_EQ(point_steps(scene, points[2]), 1000.0);
  // The first point (1000 steps) took 3 s, 2 s of them in its runs' steps.
  SweepPoint& first = points[2];
  first.runs.resize(2);
  first.runs[0].step_seconds = 0.5;
  first.runs[1].step_seconds = 1.5;
  const std::vector<const SweepPoint*> rest = {&points[0], &points[1], &points[5]};
  const MapEstimate e = estimate_map(scene, first, 3.0, rest, 2);
  EXPECT_DOUBLE_EQ(e.first_step_seconds, 2.0);
  EXPECT_EQ(e.rest_points, 3u);
  // Each other point: 1 s outside its steps, then 2 s times its steps over 1000.
  const double expected =
      (1.0 + 2.0 * 10.0 / 1000.0) + (1.0 + 2.0 * 100.0 / 1000.0) + (1.0 + 2.0 * 1000.0 / 1000.0);
  EXPECT_DOUBLE_EQ(e.rest_seconds, expected / 2.0);
  // One point left shares no jobs.
  EXPECT_DOUBLE_EQ(estimate_map(scene, first, 3.0, {&points[0]}, 4).rest_seconds,
                   1.0 + 2.0 * 10.0 / 1000.0);
}

}  // namespace
}  // namespace bb
