// Which part of a scene is wrong: the results table names the body its errors are from, the
// page folds every body's errors (a large scene's worst few per backend), and the JSON keeps
// every body's, named.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "report/json_writer.hpp"
#include "report/summary_tables.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The minimal case with `extra` more balls: ball, b1, b2, ...
Scene scene_of(int extra) {
  std::string text = test::kMinimalCase;
  for (int i = 1; i <= extra; ++i)
    text += fmt::format(
        "\n[[body]]\nname = \"b{}\"\nradius = 0.5\nmass = 1.0\nposition = [{}.0, "
        "10.0, 0.0]\n",
        i, 2 * i);
  return test::scene_from(text);
}

/// A run at report_dt whose body i is off by `off(i)` metres, everywhere.
RunRecord run_with(const Scene& scene, const std::string& backend, double (*off)(std::size_t)) {
  RunRecord run;
  run.backend = backend;
  run.dt = scene.report_dt;
  run.status = RunStatus::Ok;
  ErrorMetrics e;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    e.bodies.push_back({off(i), off(i), off(i), 0.0});
    e.position_max = std::max(e.position_max, off(i));
  }
  run.errors = e;
  return run;
}

TEST(PerBodyErrors, TheTableNamesTheWorstBodyAndTheFoldHasEachBody) {
  const Scene scene = scene_of(2);
  CaseResults results;
  results.scene = &scene;
  results.runs.push_back(
      run_with(scene, "course/rk4", [](std::size_t i) { return i == 1 ? 0.5 : 0.01; }));
  const Table t = summary_table(results, scene.report_dt);
  const auto column = std::find(t.headers.begin(), t.headers.end(), "worst body");
  ASSERT_NE(column, t.headers.end());
  EXPECT_EQ(t.rows.back()[static_cast<std::size_t>(column - t.headers.begin())], "b1");
  const PerBodyErrors each = per_body_errors(results, scene.report_dt);
  ASSERT_EQ(each.table.rows.size(), 3u);
  EXPECT_EQ(each.table.rows[0][1], "b1");  // worst first
  EXPECT_FALSE(each.cut);
  // The JSON: every body's, named, and the worst.
  const auto json = results_json(results);
  const auto& errors = json.at("runs").back().at("errors");
  EXPECT_EQ(errors.at("worst_body"), "b1");
  EXPECT_EQ(errors.at("bodies").size(), 3u);
  EXPECT_EQ(errors.at("bodies").at("b2").at("position_max"), 0.01);
}

TEST(PerBodyErrors, ALargeSceneKeepsEachBackendsWorstBodies) {
  const Scene scene = scene_of(14);
  CaseResults results;
  results.scene = &scene;
  results.runs.push_back(run_with(scene, "course/rk4", [](std::size_t i) { return 0.001 * i; }));
  const PerBodyErrors each = per_body_errors(results, scene.report_dt);
  EXPECT_TRUE(each.cut);
  ASSERT_EQ(each.table.rows.size(), kPerBodyRows);
  EXPECT_EQ(each.table.rows.front()[1], "b14");
}

TEST(PerBodyErrors, OneBodyNeedsNoName) {
  const Scene scene = scene_of(0);
  CaseResults results;
  results.scene = &scene;
  results.runs.push_back(run_with(scene, "course/rk4", [](std::size_t) { return 0.1; }));
  const Table t = summary_table(results, scene.report_dt);
  EXPECT_EQ(std::find(t.headers.begin(), t.headers.end(), "worst body"), t.headers.end());
}

}  // namespace
}  // namespace bb
