// The "Every dt" table carries each observable at every dt, so a course claim that holds at
// one step and fails at another shows its numbers on the page; cost cells show when the
// machine was busy; the order table shows its local slopes or why there is no order; the
// stability table gives bands where stability is not monotone.
#include "report/summary_tables.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "report/cost_noise.hpp"
#include "report/order_table.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

RunRecord run_at(double dt, RunStatus status, std::optional<double> apex) {
  RunRecord run;
  run.backend = "course/semi-implicit-euler";
  run.dt = dt;
  run.status = status;
  // A crashed run measured nothing; an ok one has the apex and the reference's value.
  if (status == RunStatus::Ok) run.observables.push_back({"bounce_apex/ball/1", {apex, ""}, 5.0});
  return run;
}

TEST(SweepTable, ShowsEveryObservableAtEveryDtWithItsDifferenceFromTheReference) {
  Scene scene = test::scene_from(test::kMinimalCase +
                                 std::string("\n[[observe]]\nkind = \"bounce_apex\"\nbody = "
                                             "\"ball\"\nn = 1\n"));
  CaseResults results;
  results.scene = &scene;
  results.runs = {run_at(0.02, RunStatus::Ok, 4.75), run_at(0.01, RunStatus::Ok, 5.5),
                  run_at(0.005, RunStatus::Crashed, std::nullopt)};
  const Table t = sweep_table(results);
  const auto column = std::find(t.headers.begin(), t.headers.end(), "bounce_apex/ball/1");
  ASSERT_NE(column, t.headers.end());
  const auto c = static_cast<std::size_t>(column - t.headers.begin());
  ASSERT_EQ(t.rows.size(), 3u);
  for (const auto& row : t.rows) EXPECT_EQ(row.size(), t.headers.size());
  EXPECT_EQ(t.rows[0][c], "4.75 (-0.25)");
  EXPECT_EQ(t.rows[1][c], "5.5 (0.5)");
  EXPECT_EQ(t.rows[2][c], "-");
}

TEST(SummaryTable, TheReferenceRowSaysWhatItsBracketIsFrom) {
  Scene scene = test::scene_from(test::kMinimalCase +
                                 std::string("\n[[observe]]\nkind = \"bounce_apex\"\nbody = "
                                             "\"ball\"\nn = 1\n"));
  CaseResults results;
  results.scene = &scene;
  // A value the reference measured itself has no bracket; one a formula gives (the terminal
  // speed) is named on the reference row, where "difference from the reference" is void.
  results.reference_run.backend = "reference";
  results.reference_run.observables.push_back({"bounce_apex/ball/1", {5.0, ""}, 5.0});
  Table t = summary_table(results, scene.report_dt);
  const auto c = static_cast<std::size_t>(
      std::find(t.headers.begin(), t.headers.end(), "bounce_apex/ball/1") - t.headers.begin());
  ASSERT_LT(c, t.headers.size());
  EXPECT_EQ(t.rows[0][c], "5");
  results.reference_run.observables[0].reference = 5.5;
  t = summary_table(results, scene.report_dt);
  EXPECT_EQ(t.rows[0][c], "5 (-0.5 from the formula)");
}

RunRecord timed(double dt, double median, double fastest, int repeats) {
  RunRecord run = run_at(dt, RunStatus::Ok, 5.0);
  run.cost = Cost{median, median * 1e-6, repeats, fastest, 3.0 * median, ""};
  return run;
}

// The rule: over three repeats or more, a median more than 1.25 times the fastest repeat.
// A slow outlier alone (the slowest at three times the median) says nothing.
TEST(CostNoise, AMedianFarAboveTheFastestRepeatIsMarkedAndWarnedAbout) {
  Scene scene = test::scene_from(test::kMinimalCase);
  CaseResults results;
  results.scene = &scene;
  results.runs = {timed(0.02, 100.0, 95.0, 5), timed(0.01, 100.0, 40.0, 5),
                  timed(0.005, 100.0, 10.0, 2)};
  const Table t = sweep_table(results);
  const auto column = std::find(t.headers.begin(), t.headers.end(), "ns/step");
  ASSERT_NE(column, t.headers.end());
  const auto c = static_cast<std::size_t>(column - t.headers.begin());
  EXPECT_EQ(t.rows[0][c], "100");
  EXPECT_EQ(t.rows[1][c], "~100");
  EXPECT_EQ(t.rows[2][c], "100");  // two repeats have no spread to read
  // The fastest and the slowest repeat beside the median.
  EXPECT_EQ(t.headers[c + 1], "ns/step fastest-slowest");
  EXPECT_EQ(t.rows[1][c + 1], "40-300");
  const CostNoise noise = cost_noise(results);
  EXPECT_EQ(noise.judged, 2);
  EXPECT_EQ(noise.busy, 1);
  const std::string warning = cost_noise_warning(results);
  EXPECT_NE(warning.find("in 1 of the 2 runs timed three times or more"), std::string::npos)
      << warning;
  EXPECT_NE(warning.find("up to 2.5 times"), std::string::npos) << warning;
  results.runs.erase(results.runs.begin() + 1);
  EXPECT_EQ(cost_noise_warning(results), "");
}

TEST(OrderTable, ShowsTheLocalSlopesAndWhyThereIsNoOrder) {
  Scene scene = test::scene_from(test::kMinimalCase);
  CaseResults results;
  results.scene = &scene;
  OrderFit fitted;
  fitted.slope = 1.25;
  fitted.used = 3;
  fitted.local_slopes = {{0.001, 0.002, 1.19, true},
                         {0.002, 0.004, 1.32, true},
                         {0.004, 0.008, 1.48, false},
                         {0.008, 0.016, 1.68, false}};
  OrderFit none;
  none.reason = "saturated: every error is at or above a tenth of the motion's scale (0.01 m)";
  none.local_slopes = {{0.001, 0.002, 0.44, false}};
  results.order_fits = {{"a", fitted}, {"b", none}};
  EXPECT_EQ(local_slopes_text(fitted), "[1.19 1.32] 1.48 1.68");
  const Table t = order_table(results);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][1], "1.25");
  EXPECT_EQ(t.rows[0][4], "-");
  EXPECT_EQ(t.rows[1][1], "none");
  EXPECT_EQ(t.rows[1][2], "0.44");
  EXPECT_EQ(t.rows[1][4], none.reason);
}

TEST(StabilityTable, StabilityThatIsNotMonotoneIsGivenAsBands) {
  StabilityResult r;
  r.status = "not monotone";
  r.bands = {{1e-4, 0.003, true, ""},
             {0.00301, 0.006, false, "energy grows"},
             {0.00603, 0.01, true, "energy bounded"},
             {0.0101, 0.5, false, "NaN"}};
  EXPECT_EQ(stability_bands_text(r),
            "not monotone: stable up to 0.003 s; unstable from 0.00301 to 0.006 s (energy "
            "grows); stable again from 0.00603 to 0.01 s; unstable again from 0.0101 s (NaN)");
}

}  // namespace
}  // namespace bb
