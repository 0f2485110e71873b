// The map of where each backend's outcome differs from the reference's: on a spring pair the
// reference never explodes, so explicit Euler differs exactly where its amplitude, grown by
// sqrt(1 + (omega dt)^2) a step, passes the onset (ten times the start's) within the run, and
// semi-implicit Euler exactly past the theory's 2 / omega; a point where the reference has no
// outcome says so and is never counted as the same.
#include "report/map_difference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "report/map_difference_picture.hpp"
#include "run/case_runner.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Rows k = 2, 50, 800 (omega 2, 10, 40) by steps 0.1, 0.01, 0.001 s over 1 s: explicit
/// Euler's growth over the run, (1 + (omega dt)^2)^(1 / (2 dt)), is at least a factor 3 from
/// the onset's 10 at every point (32, 1e6, 1e3 where it explodes; at most 2.2 elsewhere).
Scene small_map() {
  return test::scene_from(test::spring_map_case("differs", "[2.0, 50.0, 800.0]",
                                                "[0.1, 0.01, 0.001]",
                                                R"(["explicit-euler", "semi-implicit-euler"])"));
}

RunOptions course_only() {
  RunOptions options;
  options.backends = {"course/explicit-euler", "course/semi-implicit-euler"};
  options.cost = false;
  options.jobs = 2;
  return options;
}

/// How many times explicit Euler's amplitude grows over the 1 s run at stiffness `k`, step `dt`.
double explicit_euler_growth(double k, double dt) {
  const double h = std::sqrt(2.0 * k) * dt;
  return std::pow(1.0 + h * h, 0.5 / dt);
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(MapDifference, TheCellsThatDifferAreExactlyWhereAMethodExplodesAndTheReferenceDoesNot) {
  const Scene scene = small_map();
  const CaseResults results = run_case(scene, Registry::load(), course_only());
  ASSERT_TRUE(results.sweep);
  int explicit_differs = 0, semi_differs = 0;
  for (const SweepPoint& p : results.sweep->points) {
    // The reference follows the motion itself: it never explodes.
    for (const RunRecord& run : p.runs) {
      if (run.backend == kReferenceName) {
        ASSERT_EQ(run.status, RunStatus::Ok);
      }
    }
    const bool euler_explodes = explicit_euler_growth(p.value, p.second_value) > 10.0;
    const bool past_theory = p.second_value > 2.0 / std::sqrt(2.0 * p.value);
    const std::string at =
        "k = " + std::to_string(p.value) + ", dt = " + std::to_string(p.second_value);
    EXPECT_EQ(map_difference(scene, p, "course/explicit-euler"),
              euler_explodes ? MapDifference::Differs : MapDifference::Same)
        << at;
    EXPECT_EQ(map_difference(scene, p, "course/semi-implicit-euler"),
              past_theory ? MapDifference::Differs : MapDifference::Same)
        << at;
    explicit_differs += euler_explodes;
    semi_differs += past_theory;
  }
  // Three points for explicit Euler (k = 50 at 0.1 s, k = 800 at 0.1 and 0.01 s), one for
  // semi-implicit Euler (k = 800 at 0.1 s): neither map is all one colour.
  ASSERT_EQ(explicit_differs, 3);
  ASSERT_EQ(semi_differs, 1);
  // The picture: one dark cell per point that differs (and the legend's swatch), one panel
  // per backend but the reference.
  const std::string svg = map_differences_svg(results);
  EXPECT_EQ(count_of(svg, "fill=\"#08519c\""),
            static_cast<std::size_t>(explicit_differs + semi_differs) + 1u);
  EXPECT_EQ(count_of(svg, ">course/explicit-euler</text>"), 1u);
  EXPECT_EQ(count_of(svg, ">course/semi-implicit-euler</text>"), 1u);
  EXPECT_EQ(count_of(svg, ">reference</text>"), 0u);
  // The page's table counts them too (differs, same, no reference outcome, not run).
  std::string page = map_differences_markdown(results, map_differences_file(scene));
  page.erase(std::remove(page.begin(), page.end(), ' '), page.end());
  EXPECT_NE(page.find("|course/explicit-euler|3|6|0|0|"), std::string::npos) << page;
  EXPECT_NE(page.find("|course/semi-implicit-euler|1|8|0|0|"), std::string::npos) << page;
}

TEST(MapDifference, APointWithoutAReferenceOutcomeSaysSoAndIsNeverTheSame) {
  const Scene scene = small_map();
  CaseResults results;
  results.scene = &scene;
  results.sweep = SweepResults{"spring.1.stiffness", sweep_points(scene), "dt"};
  // Every backend ok everywhere, the reference too but at two points: unsupported at the
  // first, no row at the last.
  for (SweepPoint& p : results.sweep->points)
    for (const char* backend : {kReferenceName, "course/explicit-euler"}) {
      RunRecord run;
      run.backend = backend;
      p.runs.push_back(run);
    }
  results.sweep->points.front().runs.front().status = RunStatus::Unsupported;
  results.sweep->points.back().runs.erase(results.sweep->points.back().runs.begin());
  const std::size_t n = results.sweep->points.size();
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_EQ(map_difference(scene, results.sweep->points[i], "course/explicit-euler"),
              i == 0 || i + 1 == n ? MapDifference::NoReference : MapDifference::Same)
        << i;
  EXPECT_EQ(map_difference(scene, results.sweep->points[1], "course/semi-implicit-euler"),
            MapDifference::NotRun);
  EXPECT_NE(map_difference_words(scene, results.sweep->points.front(), "course/explicit-euler")
                .find("no reference outcome (the reference: unsupported)"),
            std::string::npos);
  // Marked with a question mark in the picture, one per such cell.
  EXPECT_EQ(count_of(map_differences_svg(results), ">?</text>"), 2u);
}

}  // namespace
}  // namespace bb
