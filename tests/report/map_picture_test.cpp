// A map's picture: the theory's boundary drawn on it is the course text's formula (2 / omega
// for semi-implicit Euler and Verlet on a spring pair, omega = sqrt(2 k) for two unit masses;
// none that is stable for explicit Euler; no line for an engine), placed along the step's axis
// between the cells of the steps around it; each point is one cell of its run's outcome.
#include "report/map_picture.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "report/map_cells.hpp"
#include "run/sweep_runner.hpp"
#include "support/spring_pair_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two unit masses on a spring, a map of its stiffness by the step.
Scene spring_map() {
  return test::scene_from(test::spring_pair_case("spring_map", "0.2", "[0.2, 0.1]", "0.1") +
                          R"([course]
integrators = ["explicit-euler", "semi-implicit-euler", "velocity-verlet"]
[[sweep]]
parameter = "spring.1.stiffness"
values = [2500.0, 100.0]
[[sweep]]
parameter = "dt"
values = [0.01, 0.02, 0.05, 0.1, 0.2]
)");
}

TEST(MapPicture, TheBoundaryIsTwoOverOmegaAtEachStiffness) {
  const Scene scene = spring_map();
  for (const char* backend : {"course/semi-implicit-euler", "course/velocity-verlet"}) {
    const std::vector<BoundaryPoint> line = map_boundary(scene, backend);
    ASSERT_EQ(line.size(), 2u) << backend;
    for (const BoundaryPoint& b : line)
      // The theory finds the limit numerically (the step matrix's spectral radius), to 1e-9.
      EXPECT_NEAR(b.limit, 2.0 / std::sqrt(2.0 * b.value), 1e-9 * b.limit)
          << backend << " " << b.value;
    EXPECT_EQ(line.front().value, 100.0);  // ascending, as the rows are drawn
  }
  // Explicit Euler grows every undamped oscillation: no step is stable.
  for (const BoundaryPoint& b : map_boundary(scene, "course/explicit-euler"))
    EXPECT_EQ(b.limit, 0.0);
  EXPECT_TRUE(map_boundary(scene, "bullet").empty());
}

TEST(MapPicture, TheLineLiesBetweenTheCellsOfTheStepsAroundTheLimit) {
  const Scene scene = spring_map();
  const double left = 64.0, top = 34.0, cell = 20.0;
  // Rows from the bottom: k = 100, then 2500. Along the steps (0.01, 0.02, 0.05, 0.1, 0.2),
  // a limit between steps k and k + 1 sits at k + 0.5 cells plus its share of the log gap.
  const auto x_of = [&](double limit, int k, double lo, double hi) {
    return left + cell * (k + 0.5 + std::log(limit / lo) / std::log(hi / lo));
  };
  const double x100 = x_of(2.0 / std::sqrt(200.0), 3, 0.1, 0.2);
  const double x2500 = x_of(2.0 / std::sqrt(5000.0), 1, 0.02, 0.05);
  const std::string expected = fmt::format("{:.2f},{:.2f} {:.2f},{:.2f}", x100,
                                           top + 2 * cell - 0.5 * cell, x2500, top + 0.5 * cell);
  EXPECT_EQ(boundary_points(scene, "course/semi-implicit-euler", left, top, cell), expected);
  // Unstable at every step: the line runs up the step axis's start.
  EXPECT_EQ(
      boundary_points(scene, "course/explicit-euler", left, top, cell),
      fmt::format("{:.2f},{:.2f} {:.2f},{:.2f}", left, top + 1.5 * cell, left, top + 0.5 * cell));
  EXPECT_EQ(boundary_points(scene, "bullet", left, top, cell), "");
}

TEST(MapPicture, EachPointIsOneCellOfItsRunsOutcome) {
  const Scene scene = spring_map();
  CaseResults results;
  results.scene = &scene;
  results.sweep = SweepResults{"spring.1.stiffness", sweep_points(scene), "dt"};
  for (SweepPoint& p : results.sweep->points) {
    RunRecord run;
    run.backend = "course/semi-implicit-euler";
    run.status =
        p.second_value > 2.0 / std::sqrt(2.0 * p.value) ? RunStatus::Diverged : RunStatus::Ok;
    p.runs.push_back(run);
  }
  const std::string svg = map_svg(results, "course/semi-implicit-euler");
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
    return n;
  };
  // k = 100: 0.2 s explodes; k = 2500: 0.05, 0.1 and 0.2 s do (and the legend's swatch).
  EXPECT_EQ(count("fill=\"#cb181d\""), 4u + 1u);
  // The cells, the frame around them and the legend's four swatches.
  EXPECT_EQ(count("<rect x="), 10u + 1u + 4u);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_EQ(map_file(scene, "course/semi-implicit-euler"),
            "spring_map-map-course-semi-implicit-euler.svg");
}

// A backend's name longer than its panel (a course variant with its floor rule) starts at
// the panel's edge and is condensed to the panel's width, never run into the next panel.
TEST(MapPicture, ALongTitleKeepsToItsPanel) {
  const Scene scene = spring_map();
  CaseResults results;
  results.scene = &scene;
  results.sweep = SweepResults{"spring.1.stiffness", sweep_points(scene), "dt"};
  const std::string name = "course/semi-implicit-euler+a-rule-with-a-long-name";
  const std::string svg = map_svg(results, name);
  const std::size_t title = svg.find(">" + name + "</text>");
  ASSERT_NE(title, std::string::npos) << svg;
  const std::size_t open = svg.rfind("<text ", title);
  const std::string tag = svg.substr(open, title - open);
  const auto attribute = [&](const std::string& key) {
    const std::size_t at = tag.find(key + "=\"");
    return at == std::string::npos ? -1.0 : std::stod(tag.substr(at + key.size() + 2));
  };
  const double x = attribute("x"), length = attribute("textLength");
  ASSERT_GT(length, 0.0) << tag;
  const double panel = map_panel_width(scene);
  EXPECT_LE(x + length, panel) << tag;
  EXPECT_GE(x, 0.0);
  // A short name keeps its place over the cells, at its natural width.
  const std::string short_svg = map_svg(results, "course/rk4");
  EXPECT_EQ(short_svg.find("textLength"), std::string::npos);
}

}  // namespace
}  // namespace bb
