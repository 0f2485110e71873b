// The paths a [[sweep]] may vary: what they name, what they refuse, and the ground's tilt,
// which turns what stands on the ground with it.
#include "study/sweep_parameter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/test_support.hpp"

namespace bb {
namespace {

/// A 1 m cube resting on a level ground, and a ball above it.
Scene block_scene() {
  return test::scene_from(R"(name = "block"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1]
[ground]
friction_static = 0.6
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [2.0, 0.5, 0.0]
[[body]]
name = "ball"
radius = 0.25
mass = 1.0
position = [0.0, 3.0, 0.0]
velocity = [1.0, 0.0, 0.0]
)");
}

TEST(SweepParameter, NamesBodiesGroundAirAndGravityAndRefusesTheRest) {
  const Scene s = block_scene();
  EXPECT_EQ(sweep_path_problem(s, "body.ball.position.y"), "");
  EXPECT_EQ(sweep_path_problem(s, "body.block.half_extents.x"), "");
  EXPECT_EQ(sweep_path_problem(s, "ground.friction_static"), "");
  EXPECT_EQ(sweep_path_problem(s, "ground.normal"), "");
  EXPECT_EQ(sweep_path_problem(s, "gravity.y"), "");
  EXPECT_NE(sweep_path_problem(s, "body.ghost.mass").find("names no body 'ghost'"),
            std::string::npos);
  EXPECT_NE(sweep_path_problem(s, "air.density").find("has no [air]"), std::string::npos);
  EXPECT_NE(sweep_path_problem(s, "body.block.radius").find("not a sphere"), std::string::npos);
  EXPECT_NE(sweep_path_problem(s, "body.ball.position.w").find("names nothing"), std::string::npos);
  EXPECT_NE(sweep_path_problem(s, "ground").find("names nothing"), std::string::npos);
  EXPECT_NE(sweep_value_problem(s, "body.ball.mass", -1.0).find("between 1e-09 and 1e+09 kg"),
            std::string::npos);
  EXPECT_NE(sweep_value_problem(s, "ground.normal", 95.0).find("between -90 and 90"),
            std::string::npos);
  // Sizes a backend cannot take (ODE aborts on a ball of 1e-200 m), and the value said back
  // as the user wrote it.
  EXPECT_NE(sweep_value_problem(s, "body.ball.radius", 1e200).find("between 1e-06 and 1e+06 m"),
            std::string::npos);
  EXPECT_NE(sweep_value_problem(s, "ground.restitution", 1.00000001).find("the value 1.00000001"),
            std::string::npos);
}

TEST(SweepParameter, SetsTheNumberThePathNames) {
  Scene s = block_scene();
  set_sweep_parameter(s, "body.ball.velocity.x", 4.0);
  set_sweep_parameter(s, "ground.friction_static", 0.2);
  EXPECT_EQ(s.bodies[1].velocity.x(), 4.0);
  EXPECT_EQ(s.ground->friction_static, 0.2);
  EXPECT_EQ(sweep_parameter_value(s, "body.ball.velocity.x"), 4.0);
}

TEST(SweepParameter, TiltingTheGroundTurnsWhatStandsOnItWithIt) {
  Scene s = block_scene();
  EXPECT_NEAR(sweep_parameter_value(s, "ground.normal"), 0.0, 1e-12);
  const double before = (s.bodies[0].position - s.ground->point).dot(s.ground->normal);
  set_sweep_parameter(s, "ground.normal", 30.0);
  const double a = 30.0 * std::numbers::pi / 180.0;
  // Level ground tilts towards +x: the normal leans that way.
  EXPECT_NEAR((s.ground->normal - Vec3(std::sin(a), std::cos(a), 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(sweep_parameter_value(s, "ground.normal"), 30.0, 1e-9);
  // The block still rests on the ground, turned by the same angle about z.
  EXPECT_NEAR((s.bodies[0].position - s.ground->point).dot(s.ground->normal), before, 1e-12);
  EXPECT_NEAR(angle_about_z(s.bodies[0].orientation), -a, 1e-12);
  // Velocities turn too; gravity does not.
  EXPECT_NEAR(s.bodies[1].velocity.norm(), 1.0, 1e-12);
  EXPECT_NEAR(s.bodies[1].velocity.y(), -std::sin(a), 1e-12);
  EXPECT_EQ(s.gravity, Vec3(0.0, -9.81, 0.0));
  // A second tilt is from level again, not on top of the first.
  set_sweep_parameter(s, "ground.normal", 10.0);
  EXPECT_NEAR(sweep_parameter_value(s, "ground.normal"), 10.0, 1e-9);
}

TEST(SweepParameter, ARangeHasCountEvenlySpacedValuesWithBothEnds) {
  const std::vector<double> v = sweep_range(9.9, 10.3, 41);
  ASSERT_EQ(v.size(), 41u);
  EXPECT_EQ(v.front(), 9.9);
  EXPECT_EQ(v.back(), 10.3);
  EXPECT_NEAR(v[1] - v[0], 0.01, 1e-12);
  EXPECT_NEAR(v[20], 10.1, 1e-12);
}

// A boat's sail: its angle (degrees), area, coefficient and heel stiffness, on a body that
// has a sail, within the loader's ranges.
TEST(SweepParameter, NamesABoatsSailAndKeepsItsAngleBetween0And90Degrees) {
  Scene s = load_case(test::source_path("cases/sail_beating.toml"));
  EXPECT_EQ(sweep_path_problem(s, "body.boat.sail.angle"), "");
  EXPECT_EQ(sweep_path_problem(s, "body.boat.sail.heel_stiffness"), "");
  EXPECT_NE(sweep_path_problem(s, "body.boat.sail.mast"), "");
  EXPECT_DOUBLE_EQ(sweep_parameter_value(s, "body.boat.sail.angle"), 15.0);
  EXPECT_NE(sweep_value_problem(s, "body.boat.sail.angle", 95.0).find("between 0 and 90"),
            std::string::npos);
  EXPECT_NE(sweep_value_problem(s, "body.boat.sail.area", 0.0), "");
  EXPECT_EQ(sweep_value_problem(s, "body.boat.sail.angle", 30.0), "");
  set_sweep_parameter(s, "body.boat.sail.angle", 30.0);
  EXPECT_DOUBLE_EQ(s.bodies[0].sail->angle, 30.0);
  EXPECT_NE(sweep_path_problem(block_scene(), "body.block.sail.angle"), "");
}

}  // namespace
}  // namespace bb
