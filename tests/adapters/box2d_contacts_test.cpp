// Box2D with contacts and impulses: momentum across a collision, pushes of exactly J/m, a
// dropped ball's bounce against the closed form, the settings that change bounces, and
// pairs the case does not list passing through each other. Skips when box2d was not built.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::setting_text;

const Backend* box2d() {
  return test::engine("box2d");
}

/// The run of `scene` at `dt`, which must end ok.
RunRecord run_ok(const Scene& scene, double dt) {
  RunRecord run = run_accuracy(*box2d(), scene, dt);
  EXPECT_EQ(run.status, RunStatus::Ok) << run.reason;
  return run;
}

#define REQUIRE_BOX2D() BB_SKIP_IF_MISSING(test::not_built({"box2d"}))

TEST(Box2dContacts, MomentumIsKeptAcrossTheFirstCollision) {
  REQUIRE_BOX2D();
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  for (double dt : scene.dt) {
    SCOPED_TRACE(dt);
    const RunRecord run = run_ok(scene, dt);
    ASSERT_TRUE(run.trajectory.events.first_collision.has_value());
    const CollisionBalance& c = *run.trajectory.events.first_collision;
    EXPECT_EQ(scene.bodies[c.body_a].name, "big");
    EXPECT_EQ(scene.bodies[c.body_b].name, "small");
    // The total momentum is about 3 N s; single precision rounds it to ~2e-7 N s, and the
    // solver's contact impulses act on both bodies equally and oppositely.
    EXPECT_LT(c.momentum_change.norm(), 1e-6);
    // The bodies did bounce off each other: the kinetic energy dropped (e = 0.9).
    EXPECT_LT(c.kinetic_energy_after, c.kinetic_energy_before);
  }
}

TEST(Box2dContacts, AnImpulseChangesVelocityByJOverM) {
  REQUIRE_BOX2D();
  const Scene scene = load_case(test::source_path("cases/push.toml"));
  for (double dt : scene.dt) {
    SCOPED_TRACE(dt);
    const RunRecord run = run_ok(scene, dt);
    // The state read at the impulse's time is before the push; the next sample after it.
    const std::size_t at = static_cast<std::size_t>(std::llround(0.5 / scene.sample));
    ASSERT_NEAR(run.trajectory.times[at], 0.5, 1e-12);
    for (const Impulse& push : scene.impulses) {
      const std::size_t i = static_cast<std::size_t>(push.body);
      const Vec3 expected = push.impulse / scene.bodies[i].mass;
      EXPECT_EQ(run.trajectory.states[at][i].velocity, Vec3::Zero());
      // Single precision: J/m is 2 or 0.5, exact in float; allow a few ulps.
      for (std::size_t j : {at + 1, run.trajectory.states.size() - 1})
        EXPECT_LT((run.trajectory.states[j][i].velocity - expected).norm(), 1e-6)
            << scene.bodies[i].name << " at " << run.trajectory.times[j];
    }
  }
}

// The issue's drop: a ball of r = 0.5 m from 10 m onto a ground with e = 0.8, long enough
// for three apexes (drop_height_sensitivity's h1000 stops after one).
const std::string kBox2dDrop =
    test::dropped_ball("8.0", "0.0166666666666666667",
                       "0.0166666666666666667, 0.00416666666666666667", "0.0166666666666666667");

TEST(Box2dContacts, ADroppedBallBouncesNearTheClosedForm) {
  REQUIRE_BOX2D();
  const Scene scene = test::scene_from(kBox2dDrop);
  const Body& ball = scene.bodies[0];
  const double g = -scene.gravity.y(), e = scene.ground->restitution;
  const double drop = ball.position.y() - ball.radius;
  const double first_contact = std::sqrt(2.0 * drop / g);
  const double impact_speed = g * first_contact;
  // The centre's apexes: e^2n times the drop, plus the radius.
  const double analytic[] = {e * e * drop + ball.radius, std::pow(e, 4) * drop + ball.radius,
                             std::pow(e, 6) * drop + ball.radius};
  // What the issue measured for Box2D on these packages (bottom of the ball, 1/60 and 1/240 s).
  const std::map<long, double> measured_in_issue = {{60, 6.245}, {240, 6.080}};
  for (double dt : scene.dt) {
    SCOPED_TRACE(dt);
    const RunRecord run = run_ok(scene, dt);
    const BodyEvents& events = run.trajectory.events.bodies[0];
    ASSERT_FALSE(events.contact_times.empty());
    EXPECT_NEAR(events.contact_times[0], first_contact, 2.0 * dt);
    ASSERT_GE(events.apex_heights.size(), 3u);
    std::printf(
        "box2d dt = 1/%.0f: apexes of the bottom %.3f / %.3f / %.3f m (analytic %.3f / "
        "%.3f / %.3f)\n",
        1.0 / dt, events.apex_heights[0] - ball.radius, events.apex_heights[1] - ball.radius,
        events.apex_heights[2] - ball.radius, analytic[0] - ball.radius, analytic[1] - ball.radius,
        analytic[2] - ball.radius);
    // The band: the time-of-impact step bounces with the end-of-step velocity, up to g dt
    // faster than at the true contact (e^2 v dt in height), the semi-implicit rise loses up
    // to e v dt / 2, and the ground's 1 cm skin and 5 mm slop move the contact.
    const double band = e * impact_speed * dt * (e + 0.5) + 0.015;
    EXPECT_NEAR(events.apex_heights[0], analytic[0], band);
    EXPECT_NEAR(events.apex_heights[0] - ball.radius, measured_in_issue.at(std::lround(1.0 / dt)),
                0.01);
  }
}

// A ground tilted by 30 degrees whose line passes through (1, 0.5): a ball dropped onto it.
const char* kSlope = R"(name = "slope"
dims = 2
duration = 1.5
sample = 0.0166666666666666667
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667

[ground]
point = [1.0, 0.5, 0.0]
normal = [0.5, 0.8660254037844386, 0.0]
restitution = 0.8

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 5.0, 0.0]
)";

TEST(Box2dContacts, ATiltedGroundLiesWhereTheCaseSaysAndBouncesAlongItsNormal) {
  REQUIRE_BOX2D();
  const Scene scene = test::scene_from(kSlope);
  const double dt = scene.report_dt, g = -scene.gravity.y(), e = scene.ground->restitution;
  const Vec3 n = scene.ground->normal;
  const Body& ball = scene.bodies[0];
  // The gap along the normal closes at g n_y t^2 / 2.
  const double gap = (ball.position - scene.ground->point).dot(n) - ball.radius;
  const double first_contact = std::sqrt(2.0 * gap / (g * n.y()));
  const RunRecord run = run_ok(scene, dt);
  const BodyEvents& events = run.trajectory.events.bodies[0];
  ASSERT_FALSE(events.contact_times.empty());
  EXPECT_NEAR(events.contact_times[0], first_contact, 2.0 * dt);
  // It leaves along the normal at e times the speed it came in with, give or take the
  // step's gravity (the time-of-impact step bounces with the end-of-step velocity).
  ASSERT_TRUE(events.post_velocity.has_value());
  const double normal_in = g * n.y() * first_contact;
  EXPECT_NEAR(events.post_velocity->dot(n), e * normal_in, (1.0 + e) * g * dt);
}

TEST(Box2dContacts, SettingsNameTheRulesThatChangeBounces) {
  REQUIRE_BOX2D();
  const Scene bounce = load_case(test::source_path("cases/double_bounce.toml"));
  const Settings s = run_ok(bounce, bounce.report_dt).engine_settings;
  EXPECT_NE(setting_text(s, "restitution_rule").find("b2MixRestitution"), std::string::npos);
  EXPECT_NE(setting_text(s, "restitution_rule").find("PreSolve"), std::string::npos);
  EXPECT_EQ(setting_text(s, "restitution_threshold"), "1");
  EXPECT_NE(setting_text(s, "restitution_threshold_rule").find("does not bounce"),
            std::string::npos);
  // Every bounce of this case is faster than 1 m/s.
  EXPECT_EQ(setting_text(s, "bounces_below_threshold"), "0");
  EXPECT_NE(setting_text(s, "linear_slop").find("0.005 m"), std::string::npos);
  EXPECT_EQ(setting_text(s, "bullet"), "false");
  EXPECT_NE(setting_text(s, "continuous_collision").find("bullet"), std::string::npos);
  EXPECT_EQ(setting_text(s, "velocity_iterations"), "8");
  EXPECT_EQ(setting_text(s, "position_iterations"), "3");
  EXPECT_NE(setting_text(s, "max_translation").find("2 m"), std::string::npos);
  const Scene push = load_case(test::source_path("cases/push.toml"));
  const Settings p = run_ok(push, push.report_dt).engine_settings;
  EXPECT_NE(setting_text(p, "impulse").find("ApplyLinearImpulse"), std::string::npos);
  // No contacts: no shapes, and no contact rules to report.
  EXPECT_NE(setting_text(p, "collision").find("none"), std::string::npos);
  EXPECT_EQ(setting_text(p, "restitution_rule"), "");
}

// Three balls on a line without gravity: "a" runs through "c", which the case does not
// pair with it, and then hits "b", which it does.
const char* kUnlistedPair = R"(name = "unlisted_pair"
dims = 2
duration = 4.0
sample = 0.25
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]

[[body]]
name = "a"
radius = 0.5
mass = 1.0
position = [-3.0, 1.0, 0.0]
velocity = [2.0, 0.0, 0.0]

[[body]]
name = "b"
radius = 0.5
mass = 1.0
position = [3.0, 1.0, 0.0]

[[body]]
name = "c"
radius = 0.5
mass = 1.0
position = [0.0, 1.0, 0.0]

[[contact]]
bodies = ["a", "b"]
restitution = 1.0

[[contact]]
bodies = ["b", "c"]
restitution = 1.0
)";

TEST(Box2dContacts, APairTheCaseDoesNotListDoesNotCollide) {
  REQUIRE_BOX2D();
  const Scene scene = test::scene_from(kUnlistedPair);
  const RunRecord run = run_ok(scene, scene.report_dt);
  // At 2.25 s "a" has passed through "c" (centres 1.5 m apart) and not yet reached "b".
  const State& passed = run.trajectory.states[9];
  ASSERT_NEAR(run.trajectory.times[9], 2.25, 1e-12);
  EXPECT_NEAR(passed[0].velocity.x(), 2.0, 1e-6);
  EXPECT_NEAR(passed[0].position.x(), 1.5, 1e-4);
  EXPECT_EQ(passed[2].velocity, Vec3::Zero());
  EXPECT_EQ(passed[2].position, Vec3(0.0, 1.0, 0.0));
  // The listed pair does collide: equal masses, e = 1, so "a" stops and "b" takes 2 m/s.
  const State& end = run.trajectory.states.back();
  EXPECT_NEAR(end[0].velocity.x(), 0.0, 1e-5);
  EXPECT_NEAR(end[1].velocity.x(), 2.0, 1e-5);
}

// A ball that reaches the ground at 0.77 m/s, below Box2D's default threshold of 1 m/s.
std::string slow_drop(const std::string& engine_table) {
  return R"(name = "slow_drop"
dims = 2
duration = 1.0
sample = 0.05
dt = [0.00416666666666666667]
report_dt = 0.00416666666666666667

[ground]
restitution = 0.8

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 0.53, 0.0]
)" + engine_table;
}

TEST(Box2dContacts, BelowTheRestitutionThresholdTheBallDoesNotBounce) {
  REQUIRE_BOX2D();
  const Scene by_default = test::scene_from(slow_drop(""));
  const RunRecord kept = run_ok(by_default, by_default.report_dt);
  // The engine's rule, not the case's e = 0.8: the ball stays down, and the settings say why.
  double highest_after_contact = 0.0;
  for (std::size_t j = 3; j < kept.trajectory.states.size(); ++j)
    highest_after_contact =
        std::max(highest_after_contact, kept.trajectory.states[j][0].position.y());
  EXPECT_LT(highest_after_contact, 0.51);
  EXPECT_NE(
      setting_text(kept.engine_settings, "restitution_threshold_rule").find("does not bounce"),
      std::string::npos);
  EXPECT_EQ(setting_text(kept.engine_settings, "bounces_below_threshold"), "1");
  // With the threshold set to zero in the case, the same drop bounces.
  const Scene no_threshold =
      test::scene_from(slow_drop("\n[engines.box2d]\nrestitution_threshold = 0.0\n"));
  const RunRecord bounced = run_ok(no_threshold, no_threshold.report_dt);
  EXPECT_EQ(setting_text(bounced.engine_settings, "restitution_threshold"), "0");
  EXPECT_EQ(setting_text(bounced.engine_settings, "bounces_below_threshold"), "0");
  ASSERT_FALSE(bounced.trajectory.events.bodies[0].apex_heights.empty());
  EXPECT_GT(bounced.trajectory.events.bodies[0].apex_heights[0], 0.51);
}

}  // namespace
}  // namespace bb
