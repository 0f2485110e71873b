// A [[sweep]] over a spring's stiffness or damping, or the [grid]'s: each point is the case
// written by hand at that value, row for row, byte for byte (every backend's status, reason,
// errors and observables).
#include <gtest/gtest.h>

#include <string>

#include "report/json_writer.hpp"
#include "run/sweep_runner.hpp"
#include "support/results_rows.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A ball hung from a fixed hook by a spring of stiffness `k` and damping `c`, a three-
/// particle rope (a one-row [grid]) of stiffness `grid_k` falling beside it; then `sweep`.
std::string hanging_ball(const std::string& k, const std::string& c, const std::string& grid_k,
                         const std::string& sweep = "") {
  return R"(name = "hanging"
dims = 2
duration = 0.5
sample = 0.05
dt = [0.05, 0.025]
report_dt = 0.025
[grid]
size = [3, 1]
origin = [3.0, 0.0, 0.0]
stiffness = )" +
         grid_k + R"(
[[body]]
name = "hook"
shape = "point"
fixed = true
position = [0.0, 2.0, 0.0]
[[body]]
name = "ball"
radius = 0.1
mass = 1.0
position = [0.3, 1.0, 0.0]
[[spring]]
bodies = ["hook", "ball"]
stiffness = )" +
         k + "\ndamping = " + c + R"(
rest_length = 1.0
[[observe]]
kind = "max_stretch"
)" + sweep;
}

/// The sweep's points against the case by hand at each value (`by_hand(i)`), every row.
void expect_points_are_the_cases_by_hand(const Scene& swept_case,
                                         const std::vector<std::string>& by_hand) {
  RunOptions options;
  options.cost = false;
  options.jobs = 2;
  const auto points =
      results_json(run_case(swept_case, Registry::load(), options))["sweep"]["points"];
  ASSERT_EQ(points.size(), by_hand.size());
  options.dts = {swept_case.report_dt};
  for (std::size_t i = 0; i < by_hand.size(); ++i) {
    const auto rows =
        results_json(run_case(test::scene_from(by_hand[i]), Registry::load(), options))["runs"];
    const auto& point = points[i]["runs"];
    ASSERT_EQ(point.size(), rows.size()) << i;
    for (std::size_t r = 0; r < rows.size(); ++r)
      EXPECT_EQ(test::row_text(point[r]), test::row_text(rows[r])) << "point " << i;
  }
}

TEST(SweepSpring, ASpringsStiffnessOrDampingPointIsTheCaseWrittenByHand) {
  expect_points_are_the_cases_by_hand(
      test::scene_from(hanging_ball("50.0", "0.5", "40.0",
                                    "[[sweep]]\nparameter = \"spring.1.stiffness\"\n"
                                    "values = [20.0, 400.0]\n")),
      {hanging_ball("20.0", "0.5", "40.0"), hanging_ball("400.0", "0.5", "40.0")});
  expect_points_are_the_cases_by_hand(
      test::scene_from(hanging_ball("50.0", "0.5", "40.0",
                                    "[[sweep]]\nparameter = \"spring.1.damping\"\n"
                                    "values = [0.0, 3.0]\n")),
      {hanging_ball("50.0", "0.0", "40.0"), hanging_ball("50.0", "3.0", "40.0")});
}

TEST(SweepSpring, AGridsStiffnessPointIsTheCaseWrittenByHand) {
  expect_points_are_the_cases_by_hand(
      test::scene_from(hanging_ball("50.0", "0.5", "40.0",
                                    "[[sweep]]\nparameter = \"grid.stiffness\"\n"
                                    "values = [10.0, 900.0]\n")),
      {hanging_ball("50.0", "0.5", "10.0"), hanging_ball("50.0", "0.5", "900.0")});
}

}  // namespace
}  // namespace bb
