// ODE with contacts and impulses: its own collision detection on the case's pairs only, the
// case's restitution on every contact's surface, impulses by setting the velocity, and the
// settings that change bounces written into the run.
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

/// ODE's own rounding in double precision.
constexpr double kPrecision = 1e-12;

class OdeContacts : public ::testing::Test {
 protected:
  void SetUp() override { BB_SKIP_IF_MISSING(test::not_built({"ode"})); }
  const Backend& ode() const { return *engine("ode"); }
};

// (a) The contact joint's impulses between the two balls are equal and opposite, so their
// total momentum, less gravity's impulse, does not change across their first collision.
TEST_F(OdeContacts, DoubleBounceKeepsMomentumAcrossTheBallsCollision) {
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const RunRecord run = run_accuracy(ode(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  ASSERT_TRUE(run.trajectory.events.first_collision.has_value()) << "the balls never met";
  const Observe momentum{"momentum_change", scene.body_index("big"), 0, 0, ""};
  const std::optional<ObservableValue> change = measure(scene, momentum, run.trajectory, nullptr);
  ASSERT_TRUE(change && change->value) << (change ? change->note : "");
  std::printf("ode: momentum change across the first collision %.3g N s at t = %.4f s\n",
              *change->value, run.trajectory.events.first_collision->time);
  // Rounding only: the balls carry about 3 N s.
  EXPECT_LT(*change->value, 1e-9);
}

// (b) Each velocity changes by exactly J / m at the step that starts at the impulse's time.
TEST_F(OdeContacts, PushChangesEachVelocityByImpulseOverMass) {
  const Scene scene = load_case(test::source_path("cases/push.toml"));
  const double dt = scene.report_dt;
  auto sim = start_case(ode(), scene, dt);
  State state(scene.bodies.size());
  const long impulse_step = std::lround(scene.impulses.front().time / dt);
  for (long k = 0; k < impulse_step; ++k) sim->step();
  // The state read at the impulse's time is before the push.
  sim->read(state);
  for (const BodyState& b : state) EXPECT_EQ(b.velocity.norm(), 0.0);
  sim->step();
  sim->read(state);
  for (const Impulse& imp : scene.impulses) {
    const Body& body = scene.bodies[static_cast<std::size_t>(imp.body)];
    EXPECT_LT((state[static_cast<std::size_t>(imp.body)].velocity - imp.impulse / body.mass).norm(),
              kPrecision)
        << body.name;
  }
  EXPECT_NE(text_setting(sim->settings(), "impulse").find("velocity set"), std::string::npos);
}

// A ball of radius 0.5 m dropped from 10 m onto a ground with restitution 0.8.
std::string drop(const std::string& dt) {
  return test::dropped_ball("9.0", "0.0166666666666666667", dt, dt);
}

// (c) The first contact comes within two steps of the closed form (ODE finds it only once
// the ball overlaps the ground), and the ball bounces with the case's restitution, give or
// take what the late detection and ERP's push out of the ground do.
TEST_F(OdeContacts, ADroppedBallBouncesWithTheCasesRestitution) {
  for (const char* step : {"0.0166666666666666667", "0.00416666666666666667"}) {
    const Scene scene = test::scene_from(drop(step));
    const double dt = scene.report_dt, g = 9.81, r = 0.5, h = 10.0, e = 0.8;
    auto sim = start_case(ode(), scene, dt);
    State state(1);
    double contact_time = -1.0, previous_vy = 0.0, deepest = 0.0;
    std::vector<double> apexes;  // of the ball's bottom, metres
    for (long k = 1; k * dt <= scene.duration + 1e-9; ++k) {
      sim->step();
      sim->read(state);
      const double vy = state[0].velocity.y();
      deepest = std::max(deepest, r - state[0].position.y());
      // The first step that turns the fall around is the contact.
      if (contact_time < 0.0 && vy > previous_vy) contact_time = k * dt;
      if (previous_vy > 0.0 && vy <= 0.0) apexes.push_back(state[0].position.y() - r);
      previous_vy = vy;
    }
    std::printf(
        "ode at dt %.5f s: first contact %.4f s (closed form %.4f s), deepest %.3f m; "
        "bottom apexes",
        dt, contact_time, std::sqrt(2.0 * (h - r) / g), deepest);
    for (double a : apexes) std::printf(" %.3f", a);
    std::printf(" m (exact %.3f %.3f %.3f)\n", e * e * (h - r), std::pow(e, 4) * (h - r),
                std::pow(e, 6) * (h - r));
    EXPECT_NEAR(contact_time, std::sqrt(2.0 * (h - r) / g), 2.0 * dt);
    ASSERT_GE(apexes.size(), 3u);
    // Lowest: e^2 (h - r) less 10% for where the step lands. Highest: the bounce plus ERP's
    // push out of a penetration of at most one step's fall, erp x v dt / dt = 0.2 v.
    EXPECT_GT(apexes[0], 0.9 * e * e * (h - r));
    EXPECT_LT(apexes[0], (e + 0.2) * (e + 0.2) * (h - r));
    EXPECT_LT(apexes[1], apexes[0]);
    EXPECT_LT(apexes[2], apexes[1]);
  }
}

// (d) What changes bounces is in the run, with the engine's rule and the adapter's answer.
TEST_F(OdeContacts, RunsWithContactsNameTheirRulesAndThresholds) {
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const RunRecord run = run_accuracy(ode(), scene, scene.report_dt);
  const Settings& s = run.engine_settings;
  EXPECT_NE(text_setting(s, "restitution_rule").find("near callback"), std::string::npos);
  EXPECT_NE(text_setting(s, "detection").find("overlap"), std::string::npos);
  for (const char* key : {"erp", "cfm", "bounce_vel", "contact_surface_layer", "contacts_made"})
    EXPECT_TRUE(setting(s, key) && std::holds_alternative<double>(*setting(s, key))) << key;
  for (const char* key : {"collision", "max_correcting_vel", "restitution_below_threshold"})
    EXPECT_NE(text_setting(s, key), "") << key;
  EXPECT_GT(std::get<double>(*setting(s, "contacts_made")), 0.0);
}

/// `x` as the docs write a number: %g, without an exponent's leading zero (1e-5, not 1e-05).
std::string doc_number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", x);
  std::string out = text;
  for (const char* zero : {"e-0", "e+0"})
    if (const std::size_t at = out.find(zero); at != std::string::npos) out.erase(at + 2, 1);
  return out;
}

// The world's cfm is beachball's choice: each run names ODE's own default beside it
// (cfm_ode_default, read from a new world), and where the two differ the docs' row of the
// key says both, the one as beachball's. It read "constraint force mixing | 1e-5", which a
// reader took for ODE's default; ODE 0.16 in double precision starts a world at 1e-10.
TEST_F(OdeContacts, TheWorldsCfmIsBeachballsChoiceNamedBesideOdesOwn) {
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  const RunRecord run = run_accuracy(ode(), scene, scene.report_dt);
  const double used = test::number_setting(run.engine_settings, "cfm");
  const double own = test::number_setting(run.engine_settings, "cfm_ode_default");
  ASSERT_TRUE(std::isfinite(own)) << "the run does not name ODE's own cfm";
  ASSERT_TRUE(std::isfinite(used));
  if (used == own) GTEST_SKIP() << "beachball's cfm is this ODE's own: nothing to tell apart";
  const std::string doc = test::bytes(test::source_path("docs/case-format.md"));
  const std::size_t section = doc.find("### `[engines.ode]`");
  ASSERT_NE(section, std::string::npos);
  const std::size_t row = doc.find("| `cfm` |", section);
  ASSERT_NE(row, std::string::npos);
  const std::string line = doc.substr(row, doc.find('\n', row) - row);
  EXPECT_NE(line.find(doc_number(used) + ": beachball's choice"), std::string::npos) << line;
  EXPECT_NE(line.find("ODE's own default is " + doc_number(own)), std::string::npos) << line;
}

// (e) Only the pairs the case lists collide; the same scene with the pair listed does.
TEST_F(OdeContacts, APairTheCaseDoesNotListPassesThrough) {
  const Scene apart = test::scene_from(three_in_a_row(R"(["a", "c"])"));
  const RunRecord through = run_accuracy(ode(), apart, apart.report_dt);
  ASSERT_EQ(through.status, RunStatus::Ok) << through.reason;
  const State& last = through.trajectory.states.back();
  EXPECT_LT((last[0].velocity - Vec3(2.0, 0.0, 0.0)).norm(), kPrecision);
  EXPECT_EQ(last[1].velocity.norm(), 0.0);
  EXPECT_GT(last[0].position.x(), 1.9);  // well past b
  const Scene listed = test::scene_from(three_in_a_row(R"(["a", "b"])"));
  const RunRecord hit = run_accuracy(ode(), listed, listed.report_dt);
  ASSERT_EQ(hit.status, RunStatus::Ok) << hit.reason;
  // Equal masses, e = 1: b leaves with about a's speed.
  EXPECT_GT(hit.trajectory.states.back()[1].velocity.x(), 1.5);
}

}  // namespace
}  // namespace bb
