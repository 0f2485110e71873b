// The reference's stick and slip against closed forms (seed section 6): on level ground a
// block at v0 stops after v0 / (mu_k g) s and v0^2 / (2 mu_k g) m; on a slope above
// atan(mu_s) it slides with g (sin - mu_k cos); below it it never moves.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "scene/load_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

constexpr double kClosedForm = 1e-9;

RunRecord reference_run(const std::string& name) {
  const Scene scene = load_case(test::source_path("cases/" + name + ".toml"));
  return run_accuracy(ReferenceBackend(), scene, scene.report_dt);
}

TEST(FrictionReference, LevelGroundStopsAtTheClosedFormsTimeAndDistance) {
  const Scene scene = load_case(test::source_path("cases/sliding_block.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const double mu_g = scene.ground->friction_kinetic * -scene.gravity.y();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    const double v0 = b.velocity.norm();
    const BodyEvents& e = run.trajectory.events.bodies[i];
    ASSERT_TRUE(e.stop_time) << b.name;
    EXPECT_NEAR(*e.stop_time, v0 / mu_g, kClosedForm) << b.name;
    EXPECT_NEAR((e.stop_position - b.position).norm(), v0 * v0 / (2.0 * mu_g), kClosedForm)
        << b.name;
    // And it stays there: the last sample is where it stopped.
    EXPECT_NEAR((run.trajectory.states.back()[i].position - e.stop_position).norm(), 0.0,
                kClosedForm)
        << b.name;
  }
}

TEST(FrictionReference, DiagonalSlideIsTheSameAsAlongAnAxis) {
  const Scene scene = load_case(test::source_path("cases/sliding_block_diagonal.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const BodyEvents& along = run.trajectory.events.bodies[0];
  const BodyEvents& diagonal = run.trajectory.events.bodies[1];
  ASSERT_TRUE(along.stop_time && diagonal.stop_time);
  EXPECT_NEAR(*diagonal.stop_time, *along.stop_time, kClosedForm);
  EXPECT_NEAR((diagonal.stop_position - scene.bodies[1].position).norm(),
              (along.stop_position - scene.bodies[0].position).norm(), kClosedForm);
}

// Above atan(mu_s) the block slides from rest: x(t) = a t^2 / 2 along the slope with
// a = g (sin theta - mu_k cos theta), and it never stops.
TEST(FrictionReference, SlopeAboveTheThresholdSlidesWithTheClosedFormsAcceleration) {
  for (const std::string name : {"slope_slide", "slope_threshold_above"}) {
    const Scene scene = load_case(test::source_path("cases/" + name + ".toml"));
    const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const Vec3 n = scene.ground->normal;
    const double g = -scene.gravity.y(), cos = n.y(), sin = std::sqrt(1.0 - cos * cos);
    const double a = g * (sin - scene.ground->friction_kinetic * cos);
    for (std::size_t j = 0; j < run.trajectory.times.size(); ++j) {
      const double t = run.trajectory.times[j];
      const Vec3 moved = run.trajectory.states[j][0].position - scene.bodies[0].position;
      ASSERT_NEAR(moved.norm(), 0.5 * a * t * t, kClosedForm) << name << " t = " << t;
      ASSERT_NEAR(moved.dot(n), 0.0, kClosedForm) << name << " left the slope at t = " << t;
    }
    EXPECT_FALSE(run.trajectory.events.bodies[0].stop_time) << name;
  }
}

// Below atan(mu_s) the block is held from the start: stopped at t = 0, never moving.
TEST(FrictionReference, SlopeBelowTheThresholdHoldsTheBlockStill) {
  for (const std::string name : {"slope_hold", "slope_threshold_below"}) {
    const RunRecord run = reference_run(name);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    EXPECT_EQ(run.trajectory.events.bodies[0].stop_time, 0.0) << name;
    for (const State& s : run.trajectory.states)
      ASSERT_EQ(s[0].position, run.trajectory.states.front()[0].position) << name;
  }
}

// Past what the reference answers exactly, it says why: a ball would roll; a tall box on
// a slope would tip over its edge before it slid.
TEST(FrictionReference, RollingAndTippingAreUnsupportedWithTheReason) {
  const std::string head = R"(name = "x"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
report_dt = 0.01
[ground]
friction_static = 0.6
friction_kinetic = 0.5
)";
  const Scene ball = test::scene_from(head + R"([[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 0.5, 0.0]
velocity = [1.0, 0.0, 0.0]
)");
  const RunRecord rolling = run_accuracy(ReferenceBackend(), ball, 0.01);
  EXPECT_EQ(rolling.status, RunStatus::Unsupported);
  EXPECT_NE(rolling.reason.find("roll"), std::string::npos) << rolling.reason;
  // A box 2 m tall and 0.5 m wide sliding: h mu_k = 1 x 0.5 beats its half width 0.25.
  const Scene tall = test::scene_from(head + R"([[body]]
name = "tower"
shape = "box"
half_extents = [0.25, 1.0, 0.25]
mass = 1.0
position = [0.0, 1.0, 0.0]
velocity = [1.0, 0.0, 0.0]
)");
  const RunRecord tipping = run_accuracy(ReferenceBackend(), tall, 0.01);
  EXPECT_EQ(tipping.status, RunStatus::Unsupported);
  EXPECT_NE(tipping.reason.find("tip"), std::string::npos) << tipping.reason;
}

}  // namespace
}  // namespace bb
