// The tunnelling bound of the course's collision test, against the course's own runs: below
// (h + r) / v the ball is turned back wherever its steps happen to land; just above it, at a
// step still short of (thickness + diameter) / v, some landing lets it through (a step that
// ends in the panel's far half pushes it out of the far face), so the bound is the half and
// not the whole.
#include "course/tunnelling_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "course/course_backend.hpp"
#include "study/start_case.hpp"
#include "support/test_support.hpp"
#include "support/thin_panel_case.hpp"

namespace bb {
namespace {

constexpr double kSpeed = 20.0, kHalfThickness = 0.01, kRadius = 0.05;

/// The ball `gap` m before the panel's near window (its surface gap), flying at kSpeed.
Scene flight(double gap) {
  return test::scene_from(R"(name = "flight"
dims = 2
duration = 1.0
sample = 0.5
dt = [0.001]
report_dt = 0.001
gravity = [0.0, 0.0, 0.0]
)" + test::ball_and_thin_panel(std::to_string(-(kHalfThickness + kRadius + gap)), "20.0"));
}

/// The ball's velocity along its flight after 0.2 s of the course at step `dt`: negative
/// when the panel turned it back.
double after_flight(const Scene& scene, double dt) {
  const CourseBackend backend({"course", "semi-implicit-euler", "clamp", "clamp"});
  auto sim = start_case(backend, scene, dt);
  for (long n = 0; n < std::lround(0.2 / dt); ++n) sim->step();
  State s(2);
  sim->read(s);
  return s[0].velocity.x();
}

TEST(TunnellingTheory, TheBoundIsHalfThicknessAndRadiusOverSpeed) {
  const std::optional<double> bound = surely_turned_back_step(flight(0.5));
  ASSERT_TRUE(bound);
  EXPECT_NEAR(*bound, (kHalfThickness + kRadius) / kSpeed, 1e-15);
}

TEST(TunnellingTheory, BelowTheBoundEveryLandingTurnsTheBallBackAndAboveSomeDoNot) {
  const double bound = (kHalfThickness + kRadius) / kSpeed;
  // The steps' landings against the panel, spread over one step's travel by the start.
  int passed_below = 0, passed_above = 0;
  const int landings = 40;
  for (int k = 0; k < landings; ++k) {
    const double below = 0.99 * bound, above = 1.5 * bound;
    passed_below += after_flight(flight(0.5 + k * kSpeed * below / landings), below) > 0.0;
    passed_above += after_flight(flight(0.5 + k * kSpeed * above / landings), above) > 0.0;
  }
  EXPECT_EQ(passed_below, 0);
  // 1.5 (h + r) is short of the whole window 2 (h + r), so every landing is seen; a third of
  // them end in the far half (between h + r and 1.5 (h + r) past the near edge).
  EXPECT_GT(passed_above, 0);
  EXPECT_LT(1.5 * bound * kSpeed, 2.0 * (kHalfThickness + kRadius));
}

TEST(TunnellingTheory, CoversOnlyABallFlyingStraightAtAFixedBox) {
  Scene falling = flight(0.5);
  falling.gravity = Vec3(0.0, -9.81, 0.0);
  EXPECT_FALSE(surely_turned_back_step(falling));
  Scene sideways = flight(0.5);
  sideways.bodies[0].velocity = Vec3(20.0, 1.0, 0.0);
  EXPECT_FALSE(surely_turned_back_step(sideways));
  Scene past = flight(0.5);
  past.bodies[0].position.x() = 0.5;  // beyond the panel, flying away
  EXPECT_FALSE(surely_turned_back_step(past));
}

}  // namespace
}  // namespace bb
