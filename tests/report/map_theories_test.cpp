// The boundaries the map cases draw besides the spring's: Coulomb's law on the friction map,
// atan(mu_s) at each static friction, drawn on every backend's map where the tilt axis puts
// it (a range of tilts is evenly spaced, so the line sits linearly between the rows around
// it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "report/map_cells.hpp"
#include "report/map_picture.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A unit cube at rest on a level ground (mu_k = 0.25), tilted by the first [[sweep]].
Scene friction_map() {
  return test::scene_from(R"(name = "friction"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[ground]
restitution = 0.0
friction_static = 0.6
friction_kinetic = 0.25
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [0.0, 0.5, 0.0]
[course]
integrators = ["semi-implicit-euler"]
[[observe]]
kind = "final_velocity"
body = "block"
[[sweep]]
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

}  // namespace
}  // namespace bb
