// Bullet with contacts and impulses: its own collision detection on the case's pairs only,
// the case's restitution per pair, impulses through applyImpulse, and the settings that
// change bounces written into the run. Both builds, double and float, when they were built.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::engine;
using test::setting;
using test::text_setting;
using test::three_in_a_row;

/// Bullet's own rounding: a double build keeps about 1e-12 here, a float one 1e-6.
double precision_of(const std::string& name) {
  return name == "bullet" ? 1e-12 : 1e-6;
}

class BulletContacts : public ::testing::TestWithParam<std::string> {
 protected:
  const Backend* backend() const { return engine(GetParam()); }
};

INSTANTIATE_TEST_SUITE_P(Builds, BulletContacts, ::testing::Values("bullet", "bullet-float"),
                         [](const auto& info) {
                           return info.param == "bullet" ? std::string("double")
                                                         : std::string("float");
                         });

// (a) The contact impulses between the two balls are equal and opposite, so their total
// momentum, less gravity's impulse, does not change across their first collision.
TEST_P(BulletContacts, DoubleBounceKeepsMomentumAcrossTheBallsCollision) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const RunRecord run = run_accuracy(*backend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  ASSERT_TRUE(run.trajectory.events.first_collision.has_value()) << "the balls never met";
  const Observe momentum{"momentum_change", scene.body_index("big"), 0, 0, ""};
  const std::optional<ObservableValue> change = measure(scene, momentum, run.trajectory, nullptr);
  ASSERT_TRUE(change && change->value) << (change ? change->note : "");
  // Rounding only: the balls carry about 3 N s; a float build rounds each velocity to ~1e-6.
  const double tolerance = test::single_precision(GetParam()) ? 1e-5 : 1e-9;
  std::printf("%s: momentum change across the first collision %.3g N s at t = %.4f s\n",
              GetParam().c_str(), *change->value, run.trajectory.events.first_collision->time);
  EXPECT_LT(*change->value, tolerance);
}

// (b) Each velocity changes by exactly J / m at the step that starts at the impulse's time.
TEST_P(BulletContacts, PushChangesEachVelocityByImpulseOverMass) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene scene = load_case(test::source_path("cases/push.toml"));
  const double dt = scene.report_dt;
  auto sim = start_case(*backend(), scene, dt);
  State state(scene.bodies.size());
  const long impulse_step = std::lround(scene.impulses.front().time / dt);
  for (long k = 0; k < impulse_step; ++k) sim->step();
  // The state read at the impulse's time is before the push.
  sim->read(state);
  for (const BodyState& b : state) EXPECT_EQ(b.velocity.norm(), 0.0);
  sim->step();
  sim->read(state);
  const double tolerance = precision_of(GetParam());
  for (const Impulse& imp : scene.impulses) {
    const Body& body = scene.bodies[static_cast<std::size_t>(imp.body)];
    const Vec3 expected = imp.impulse / body.mass;
    EXPECT_LT((state[static_cast<std::size_t>(imp.body)].velocity - expected).norm(), tolerance)
        << body.name;
  }
  EXPECT_NE(text_setting(sim->settings(), "impulse").find("applyImpulse"), std::string::npos);
}

// A ball of radius 0.5 m dropped from 10 m onto a ground with restitution 0.8, at 1/240 s.
const std::string kBulletDrop = test::dropped_ball(
    "9.0", "0.0333333333333333333", "0.00416666666666666667", "0.00416666666666666667");

// (c) The first contact comes when the closed form says, and the ball bounces with the
// case's restitution, give or take what Bullet's penetration recovery adds.
TEST_P(BulletContacts, ADroppedBallBouncesWithTheCasesRestitution) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene scene = test::scene_from(kBulletDrop);
  const double dt = scene.report_dt, g = 9.81, r = 0.5, h = 10.0, e = 0.8;
  auto sim = start_case(*backend(), scene, dt);
  State state(1);
  double contact_time = -1.0;
  double previous_vy = 0.0;
  std::vector<double> apexes;  // of the ball's bottom, metres
  for (long k = 1; k * dt <= scene.duration + 1e-9; ++k) {
    sim->step();
    sim->read(state);
    const double vy = state[0].velocity.y();
    // The first step that turns the fall around is the contact.
    if (contact_time < 0.0 && vy > previous_vy) contact_time = k * dt;
    if (previous_vy > 0.0 && vy <= 0.0) apexes.push_back(state[0].position.y() - r);
    previous_vy = vy;
  }
  std::printf("%s at 1/240 s: first contact %.4f s (closed form %.4f s); bottom apexes",
              GetParam().c_str(), contact_time, std::sqrt(2.0 * (h - r) / g));
  for (double a : apexes) std::printf(" %.3f", a);
  std::printf(" m (exact %.3f %.3f %.3f)\n", e * e * (h - r), std::pow(e, 4) * (h - r),
              std::pow(e, 6) * (h - r));
  EXPECT_NEAR(contact_time, std::sqrt(2.0 * (h - r) / g), 2.0 * dt);
  ASSERT_GE(apexes.size(), 3u);
  // Lowest: the exact e^2 (h - r) less 10% for the speed lost to where the step lands.
  // Highest: the push a penetration just shallower than the split-impulse threshold (0.04 m)
  // gets through the velocity, contact_erp 0.2 x 0.04 m / dt, on top of e v_impact.
  const double v_impact = std::sqrt(2.0 * g * (h - r));
  const double lowest = 0.9 * e * e * (h - r);
  const double push = 0.2 * 0.04 / dt;
  const double highest = std::pow(e * v_impact + push, 2) / (2.0 * g);
  EXPECT_GT(apexes[0], lowest);
  EXPECT_LT(apexes[0], highest);
  // Each later bounce loses height: the ball does not gain energy without end.
  EXPECT_LT(apexes[1], apexes[0]);
  EXPECT_LT(apexes[2], apexes[1]);
}

// (d) What changes bounces is in the run, with the engine's rule and the adapter's answer.
TEST_P(BulletContacts, RunsWithContactsNameTheirRulesAndThresholds) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const RunRecord run = run_accuracy(*backend(), scene, scene.report_dt);
  const Settings& s = run.engine_settings;
  const std::string rule = text_setting(s, "restitution_rule");
  EXPECT_NE(rule.find("multiplies"), std::string::npos) << rule;
  EXPECT_NE(rule.find("gContactAddedCallback"), std::string::npos) << rule;
  EXPECT_NE(text_setting(s, "restitution_below_threshold").find("restitutionCurve"),
            std::string::npos);
  for (const char* key : {"restitution_velocity_threshold", "split_impulse_depth", "contact_erp",
                          "warm_starting_factor", "collision_margin_min", "collision_margin_max",
                          "contact_breaking_threshold_max"})
    EXPECT_TRUE(setting(s, key) && std::holds_alternative<double>(*setting(s, key))) << key;
  for (const char* key : {"split_impulse", "warm_starting", "ccd"})
    EXPECT_TRUE(setting(s, key) && std::holds_alternative<bool>(*setting(s, key))) << key;
  for (const char* key : {"collision_margin", "contact_breaking_threshold",
                          "contact_processing_threshold", "penetration_recovery"})
    EXPECT_NE(text_setting(s, key), "") << key;
  EXPECT_DOUBLE_EQ(std::get<double>(*setting(s, "restitution_velocity_threshold")), 0.2);
  // Both balls are spheres: the margin is the radius, 0.5 m to 1 m.
  EXPECT_DOUBLE_EQ(std::get<double>(*setting(s, "collision_margin_min")), 0.5);
  EXPECT_DOUBLE_EQ(std::get<double>(*setting(s, "collision_margin_max")), 1.0);
  // 0.02 x the bounding radius, which Bullet takes from the box around the sphere: sqrt(3) r.
  EXPECT_NEAR(std::get<double>(*setting(s, "contact_breaking_threshold_min")),
              0.02 * std::sqrt(3.0) * 0.5, 1e-6);
}

// (e) Only the pairs the case lists collide; the same scene with the pair listed does.
TEST_P(BulletContacts, APairTheCaseDoesNotListPassesThrough) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene apart = test::scene_from(three_in_a_row(R"(["a", "c"])"));
  const RunRecord through = run_accuracy(*backend(), apart, apart.report_dt);
  ASSERT_EQ(through.status, RunStatus::Ok) << through.reason;
  const State& last = through.trajectory.states.back();
  EXPECT_LT((last[0].velocity - Vec3(2.0, 0.0, 0.0)).norm(), precision_of(GetParam()));
  EXPECT_EQ(last[1].velocity.norm(), 0.0);
  EXPECT_GT(last[0].position.x(), 1.9);  // well past b

  const Scene listed = test::scene_from(three_in_a_row(R"(["a", "b"])"));
  const RunRecord hit = run_accuracy(*backend(), listed, listed.report_dt);
  ASSERT_EQ(hit.status, RunStatus::Ok) << hit.reason;
  // Equal masses, e = 1: b leaves with a's speed (give or take the step's penetration push).
  EXPECT_GT(hit.trajectory.states.back()[1].velocity.x(), 1.5);
}

// Without CCD, as Bullet starts, the 50 m/s ball passes the 2 cm panel at 60 Hz; with the
// ccd key its swept sphere stops it (a CCD contact has restitution 0, so it bounces back
// slower than e v), as a user who turns CCD on sees.
TEST_P(BulletContacts, TheFastBallTunnelsUnlessCcdIsOn) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  std::ifstream file(test::source_path("cases/tunnelling.toml"));
  std::stringstream text;
  text << file.rdbuf();
  const Scene off = test::scene_from(text.str());
  const Scene on = test::scene_from(text.str() + "\n[engines.bullet]\nccd = true\n");
  const RunRecord passes = run_accuracy(*backend(), off, off.report_dt);
  const RunRecord stops = run_accuracy(*backend(), on, on.report_dt);
  ASSERT_EQ(passes.status, RunStatus::Ok) << passes.reason;
  ASSERT_EQ(stops.status, RunStatus::Ok) << stops.reason;
  const BodyState& through = passes.trajectory.states.back()[0];
  const BodyState& back = stops.trajectory.states.back()[0];
  std::printf("%s: final x without CCD %.3f m (v %.2f m/s), with CCD %.3f m (v %.2f m/s)\n",
              GetParam().c_str(), through.position.x(), through.velocity.x(), back.position.x(),
              back.velocity.x());
  EXPECT_GT(through.position.x(), 0.0);
  EXPECT_DOUBLE_EQ(through.velocity.x(), 50.0);
  EXPECT_LT(back.position.x(), 0.0);
  EXPECT_LT(back.velocity.x(), 0.0);
  EXPECT_GT(back.velocity.x(), -25.0);  // slower than e v: the CCD contact took its bounce
  EXPECT_NE(text_setting(stops.engine_settings, "ccd_contacts"), "");
}

// Without gravity, a ball that touches the ground moves into it at 0.15 m/s, below Bullet's
// restitution velocity threshold (0.2 m/s): it stops though e = 1, and the run says why.
// With the threshold at 0 it leaves at 0.15 m/s. (It starts touching: a ball that drifts
// in from a gap loses its bounce at any threshold, as Bullet takes the gap off each step's
// target speed, e v - d / dt.)
std::string slow_approach(const std::string& engines) {
  return std::string(R"(name = "slow_approach"
dims = 2
duration = 2.0
sample = 0.00416666666666666667
dt = [0.00416666666666666667]
report_dt = 0.00416666666666666667
gravity = [0.0, 0.0, 0.0]
[ground]
restitution = 1.0
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 0.5, 0.0]
velocity = [0.0, -0.15, 0.0]
)") + engines;
}

TEST_P(BulletContacts, ABounceBelowTheRestitutionThresholdIsLost) {
  BB_SKIP_IF_MISSING(test::not_built({GetParam()}));
  const Scene engine_default = test::scene_from(slow_approach(""));
  const Scene no_threshold =
      test::scene_from(slow_approach("[engines.bullet]\nrestitution_velocity_threshold = 0.0\n"));
  const RunRecord stops = run_accuracy(*backend(), engine_default, engine_default.report_dt);
  const RunRecord leaves = run_accuracy(*backend(), no_threshold, no_threshold.report_dt);
  ASSERT_EQ(stops.status, RunStatus::Ok) << stops.reason;
  ASSERT_EQ(leaves.status, RunStatus::Ok) << leaves.reason;
  const double v_stops = stops.trajectory.states.back()[0].velocity.y();
  const double v_leaves = leaves.trajectory.states.back()[0].velocity.y();
  std::printf("%s: speed after the contact %.4g m/s at the default threshold, %.4g m/s at 0\n",
              GetParam().c_str(), v_stops, v_leaves);
  EXPECT_LT(std::abs(v_stops), 1e-6);
  EXPECT_NEAR(v_leaves, 0.15, precision_of(GetParam()));
  EXPECT_NE(text_setting(stops.engine_settings, "restitution_below_threshold"), "");
}

}  // namespace
}  // namespace bb
