// rest_on = "ground": a body placed exactly on the ground, a box turned to the slope with its
// face on it, so the reference follows it (not its fallback); and a body written by hand a
// hair's breadth off the ground is told so at load, with the gap and the fix.
#include "model/rest_on.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "model/initial_overlap.hpp"
#include "reference/sliding_modes.hpp"
#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A 2D case on a ground tilted `degrees` (its normal [-sin, cos]: the slope rises towards
/// +x), mu_s 0.7 and mu_k 0.5, holding the [[body]] lines `body`.
std::string on_a_slope(double degrees, const std::string& body) {
  const double a = degrees * M_PI / 180.0;
  char ground[256];
  std::snprintf(ground, sizeof ground, "normal = [%.17g, %.17g, 0.0]\n", -std::sin(a), std::cos(a));
  return R"(name = "slope"
dims = 2
duration = 0.5
sample = 0.05
dt = [0.05, 0.025]
report_dt = 0.025
[ground]
)" + std::string(ground) +
         R"(friction_static = 0.7
friction_kinetic = 0.5
[[body]]
name = "crate"
)" + body;
}

const char* kCrate = R"(shape = "box"
half_extents = [0.4, 0.25, 0.3]
mass = 2.0
)";

/// The heights above the ground's plane of a box's eight corners, lowest first.
std::vector<double> corner_heights(const Body& box, const Ground& g) {
  std::vector<double> heights;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 local{corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0};
    const Vec3 at = box.position + box.orientation * local.cwiseProduct(box.half_extents);
    heights.push_back((at - g.point).dot(g.normal));
  }
  std::sort(heights.begin(), heights.end());
  return heights;
}

/// A point's part along the ground's plane (its height along the normal taken out).
Vec3 along_plane(const Vec3& x, const Ground& g) {
  return (x - g.point) - (x - g.point).dot(g.normal) * g.normal;
}

TEST(RestOn, ACrateOnAThirtyDegreeSlopeLiesFlatOnItsLowestFace) {
  const Scene scene = test::scene_from(
      on_a_slope(30.0, std::string(kCrate) + "rest_on = \"ground\"\nposition = [1.5, 4.0, 0.0]\n"));
  const Body& crate = scene.bodies[0];
  const Ground& g = *scene.ground;
  // Four corners on the plane, four at the box's height above it: flat on a face.
  const std::vector<double> heights = corner_heights(crate, g);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(heights[k], 0.0, 1e-12) << k;
  for (int k = 4; k < 8; ++k) EXPECT_NEAR(heights[k], 0.5, 1e-12) << k;
  // The given position's part along the slope is kept.
  EXPECT_NEAR((along_plane(crate.position, g) - along_plane({1.5, 4.0, 0.0}, g)).norm(), 0.0,
              1e-12);
  // The reference follows it: none of its reasons to fall back.
  EXPECT_EQ(box_slide_reason(scene, 0), "");
}

TEST(RestOn, PlacesSpheresAndTurnedBoxesOnATiltedGroundIn3D) {
  const Scene scene = test::scene_from(R"(name = "tilted"
dims = 3
duration = 0.5
sample = 0.05
dt = [0.05]
[ground]
point = [0.5, -1.0, 2.0]
normal = [0.3, 0.9, -0.2]
friction_static = 0.9
[[body]]
name = "crate"
shape = "box"
half_extents = [0.4, 0.25, 0.3]
mass = 2.0
rest_on = "ground"
position = [1.0, 7.0, -3.0]
[[body]]
name = "ball"
radius = 0.35
mass = 1.0
rest_on = "ground"
position = [-2.0, -5.0, 1.0]
)");
  const Ground& g = *scene.ground;
  const Body& crate = scene.bodies[0];
  const std::vector<double> heights = corner_heights(crate, g);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(heights[k], 0.0, 1e-12) << k;
  EXPECT_NEAR((along_plane(crate.position, g) - along_plane({1.0, 7.0, -3.0}, g)).norm(), 0.0,
              1e-12);
  const Body& ball = scene.bodies[1];
  EXPECT_NEAR((ball.position - g.point).dot(g.normal), 0.35, 1e-12);
  EXPECT_NEAR((along_plane(ball.position, g) - along_plane({-2.0, -5.0, 1.0}, g)).norm(), 0.0,
              1e-12);
}

/// The crate written by hand at `angle` degrees, its centre `lift` above its resting height
/// along the 30-degree slope's normal: the student's case.
std::string crate_by_hand(double angle, double lift) {
  const double a = 30.0 * M_PI / 180.0;
  const Vec3 n{-std::sin(a), std::cos(a), 0.0};
  const Vec3 centre = Vec3{2.0 * std::cos(a), 2.0 * std::sin(a), 0.0} + (0.25 + lift) * n;
  char body[256];
  std::snprintf(body, sizeof body, "angle = %.17g\nposition = [%.17g, %.17g, 0.0]\n", angle,
                centre.x(), centre.y());
  return on_a_slope(30.0, std::string(kCrate) + body);
}

std::string load_error(const std::string& text) {
  try {
    test::scene_from(text);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TEST(RestOn, ACrateAHairAboveOrInsideTheSlopeIsToldTheGapAndTheFix) {
  // Line 17 is the crate's position.
  EXPECT_EQ(load_error(crate_by_hand(30.0, 2.4e-6)),
            "inline.toml:17: body 'crate' starts 2.4e-06 m above the ground: set rest_on = "
            "\"ground\" to place it on it");
  EXPECT_EQ(load_error(crate_by_hand(30.0, -3e-5)),
            "inline.toml:17: body 'crate' starts 3e-05 m inside the ground: set rest_on = "
            "\"ground\" to place it on it");
  // Within rounding it is on the ground; clearly above (a drop), it is meant to fall.
  EXPECT_EQ(load_error(crate_by_hand(30.0, 1e-12)), "");
  EXPECT_EQ(load_error(crate_by_hand(30.0, 0.01)), "");
}

TEST(RestOn, ABoxTurnedAHairFromFlatIsToldTheTurn) {
  Ground g;
  g.normal = Vec3(-0.5, std::sqrt(3.0) / 2.0, 0.0);
  Body box;
  box.name = "crate";
  box.shape = Shape::Box;
  box.half_extents = {0.4, 0.25, 0.3};
  // The slope's own turn, and 1e-5 rad more, its lowest corner on the plane.
  box.orientation = quat_from_axis_angle(Vec3::UnitZ(), M_PI / 6.0 + 1e-5);
  box.position += ground_depth(box, g) * g.normal;
  EXPECT_EQ(near_ground_miss(box, g), "is turned 0.000573 degrees from flat on the ground");
  // Placed on the ground, nothing to say; a box standing on its edge is meant to.
  place_on_ground(box, g);
  EXPECT_EQ(near_ground_miss(box, g), "");
  box.orientation = quat_from_axis_angle(Vec3::UnitZ(), M_PI / 4.0);
  box.position += ground_depth(box, g) * g.normal;
  EXPECT_EQ(near_ground_miss(box, g), "");
  // A ball a hair above the ground lands on it (or is on its way): nothing to say.
  Body ball;
  ball.radius = 0.5;
  ball.position = (0.5 + 2.4e-6) * g.normal;
  EXPECT_EQ(near_ground_miss(ball, g), "");
}

TEST(RestOn, IsRefusedWithoutAGroundOnAnythingElseAndBesideABoxsOwnTurn) {
  EXPECT_NE(load_error(on_a_slope(30.0, std::string(kCrate) + "rest_on = \"table\"\n"))
                .find("'rest_on' \"table\" is neither \"ground\" nor a body"),
            std::string::npos);
  EXPECT_NE(
      load_error(on_a_slope(30.0, std::string(kCrate) + "rest_on = \"ground\"\nangle = 30.0\n"))
          .find("leave 'angle' out"),
      std::string::npos);
  std::string no_ground = test::kMinimalCase;
  no_ground += "rest_on = \"ground\"\n";
  EXPECT_NE(load_error(no_ground).find("rests on the ground, and the case has no [ground]"),
            std::string::npos);
}

}  // namespace
}  // namespace bb
