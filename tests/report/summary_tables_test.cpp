// The "Every dt" table carries each observable at every dt, so a course claim that holds at
// one step and fails at another shows its numbers on the page.
#include "report/summary_tables.hpp"

#include <gtest/gtest.h>

#include <algorithm>

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

}  // namespace
}  // namespace bb
