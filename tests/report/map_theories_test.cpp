// The boundaries the map cases draw besides the spring's: Coulomb's law on the friction map,
// atan(mu_s) at each static friction, drawn on every backend's map where the tilt axis puts
// it (a range of tilts is evenly spaced, so the line sits linearly between the rows around
// it); and on the tunnelling map, the step below which the course's test surely turns the
// ball back, (h + r) / v at each speed, on a course variant's map only.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "report/map_cells.hpp"
#include "report/map_picture.hpp"
#include "support/block_on_ground_case.hpp"
#include "support/test_support.hpp"
#include "support/thin_panel_case.hpp"

namespace bb {
namespace {

/// A unit cube at rest on a level ground (mu_k = 0.25), tilted by the first [[sweep]].
Scene friction_map() {
  return test::scene_from(test::block_on_ground_case("friction") + R"([[sweep]]
parameter = "ground.normal"
range = [12.0, 48.0, 7]
[[sweep]]
parameter = "ground.friction_static"
values = [1.1, 0.3, 0.5, 0.9]
)");
}

double degrees_atan(double mu) {
  return std::atan(mu) * 180.0 / std::numbers::pi;
}

TEST(MapTheories, TheFrictionMapsBoundaryIsAtanMuSAtEachColumn) {
  const Scene scene = friction_map();
  const double left = 64.0, top = 34.0, cell = 20.0;
  const std::vector<double> mus = {0.3, 0.5, 0.9, 1.1};  // the columns, ascending
  for (const char* backend : {"reference", "course/semi-implicit-euler", "bullet"}) {
    const std::vector<BoundaryPoint> line = map_boundary(scene, backend);
    ASSERT_EQ(line.size(), mus.size()) << backend;
    for (std::size_t c = 0; c < mus.size(); ++c) {
      EXPECT_EQ(line[c].value, mus[c]) << backend;
      EXPECT_NEAR(line[c].limit, degrees_atan(mus[c]), 1e-12) << backend;
    }
    // Drawn: one point per column at its middle, at the height of atan(mu_s) on the tilt
    // axis (7 rows from 12 to 48 degrees, 6 degrees a row, row k's middle k + 0.5 cells up).
    const std::string points = boundary_points(scene, backend, left, top, cell);
    std::size_t at = 0;
    for (std::size_t c = 0; c < mus.size(); ++c) {
      const std::size_t comma = points.find(',', at), space = points.find(' ', comma);
      const double x = std::stod(points.substr(at, comma - at));
      const double y = std::stod(points.substr(comma + 1, space - comma - 1));
      EXPECT_NEAR(x, left + cell * (static_cast<double>(c) + 0.5), 0.005) << backend;
      const double tilt = 12.0 + 6.0 * ((top + 7.0 * cell - y) / cell - 0.5);
      // The picture rounds to 0.01 px: a 20 px row of 6 degrees.
      EXPECT_NEAR(tilt, degrees_atan(mus[c]), 0.005 * 6.0 / cell + 1e-9) << backend << " " << c;
      at = space == std::string::npos ? points.size() : space + 1;
    }
    ASSERT_NE(map_theory(scene, backend), nullptr);
    EXPECT_EQ(map_theory(scene, backend)->bounded, "ground.normal");
  }
}

/// A 5 cm ball flying at a 2 cm panel 1 m away, its speed by the step.
Scene tunnelling_map(const std::string& ground_rule) {
  return test::scene_from(R"(name = "tunnelling"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
gravity = [0.0, 0.0, 0.0]
)" + test::ball_and_thin_panel("-1.0", "8.0") +
                          R"([course]
integrators = ["semi-implicit-euler"]
ground = [")" + ground_rule +
                          R"("]
[[sweep]]
parameter = "body.ball.velocity.x"
values = [32.0, 2.0, 8.0]
[[sweep]]
parameter = "dt"
values = [0.1, 0.05, 0.025, 0.0125]
)");
}

TEST(MapTheories, TheTunnellingMapsBoundaryIsHalfThicknessAndRadiusOverSpeed) {
  const Scene scene = tunnelling_map("clamp");
  const std::vector<BoundaryPoint> line = map_boundary(scene, "course/semi-implicit-euler");
  const std::vector<double> speeds = {2.0, 8.0, 32.0};
  ASSERT_EQ(line.size(), speeds.size());
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    EXPECT_EQ(line[k].value, speeds[k]);
    EXPECT_NEAR(line[k].limit, (0.01 + 0.05) / speeds[k], 1e-15);
  }
  EXPECT_EQ(map_theory(scene, "course/semi-implicit-euler")->bounded, "dt");
  // The course's test, not an engine's or the reference's; nor under the reflect rule, which
  // leaves the ball inside to be turned again.
  for (const char* other : {"reference", "bullet", "box2d"})
    EXPECT_TRUE(map_boundary(scene, other).empty()) << other;
  EXPECT_TRUE(map_boundary(tunnelling_map("reflect"), "course/semi-implicit-euler").empty());
}

}  // namespace
}  // namespace bb
