// The reference's stick and slip against closed forms (seed section 6): on level ground a
// block at v0 stops after v0 / (mu_k g) s and v0^2 / (2 mu_k g) m; on a slope above
// atan(mu_s) it slides with g (sin - mu_k cos); below it it never moves.
#include <gtest/gtest.h>

#include <cmath>

#include "observe/observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
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

// A ball bouncing on a ground with friction meets Coulomb's law at each impact: it grips
// (the contact point stops slipping: a shell keeps 3/5 of its speed along the ground and
// rolls) when mu_s j_n allows, and slides with mu_k j_n when it does not. A ball that
// comes to rest on such a ground would roll: the reference says so when it gets there.
TEST(FrictionReference, ABallBouncingOnAGroundWithFrictionMeetsCoulombAtEachImpact) {
  const auto scene = [](double mu) {
    return test::scene_from(R"(name = "x"
dims = 2
duration = 0.5
sample = 0.05
dt = [0.01]
report_dt = 0.01
[ground]
restitution = 1.0
friction_static = )" + std::to_string(mu) +
                            R"(
friction_kinetic = )" + std::to_string(mu) +
                            R"(
[[body]]
name = "ball"
radius = 0.5
mass = 0.25
shell = true
position = [0.0, 0.5001, 0.0]
velocity = [4.0, -3.0, 0.0]
)");
  };
  for (const double mu : {0.5, 0.1}) {
    const Scene s = scene(mu);
    const RunRecord r = run_accuracy(ReferenceBackend(), s, 0.01);
    ASSERT_EQ(r.status, RunStatus::Ok) << r.reason;
    const BodyState& end = r.trajectory.states.back()[0];
    const double vn = std::sqrt(9.0 + 2.0 * 9.81 * 0.0001);
    // Gripping needs 2/5 m v_t against mu (1 + e) m v_n.
    const bool grips = 0.4 * 4.0 <= mu * 2.0 * vn;
    const double vt = grips ? 0.6 * 4.0 : 4.0 - mu * 2.0 * vn;
    // The shell's spin: the tangential impulse's moment over 2/3 m r^2.
    const double spin = -(4.0 - vt) * 0.25 * 0.5 / (2.0 / 3.0 * 0.25 * 0.25);
    EXPECT_EQ(grips, mu == 0.5);
    EXPECT_NEAR(end.velocity.x(), vt, 1e-9) << mu;
    EXPECT_NEAR(end.angular_velocity.z(), spin, 1e-9) << mu;
    if (grips) {
      EXPECT_NEAR(end.velocity.x() + end.angular_velocity.z() * 0.5, 0.0, 1e-9);
    }
  }
  // Ever smaller bounces (e = 0.5) end at rest, where the ball would roll.
  std::string text = R"(name = "x"
dims = 2
duration = 5.0
sample = 0.05
dt = [0.01]
report_dt = 0.01
[ground]
restitution = 0.5
friction_static = 0.5
friction_kinetic = 0.5
[[body]]
name = "ball"
radius = 0.5
mass = 0.25
position = [0.0, 1.5, 0.0]
velocity = [1.0, 0.0, 0.0]
)";
  const RunRecord rests = run_accuracy(ReferenceBackend(), test::scene_from(text), 0.01);
  EXPECT_EQ(rests.status, RunStatus::Unsupported);
  EXPECT_NE(rests.reason.find("roll"), std::string::npos) << rests.reason;
}

/// A 2 kg cube at rest on level ground (mu_s 0.4, mu_k 0.3) pushed along x by `impulse`
/// N s at 0.5 s, observed for 3 s.
Scene pushed_block(const std::string& impulses) {
  return test::scene_from(test::pushed_block_case(impulses));
}

// A block at rest pushed at 0.5 s: its stop is the end of that motion, measured from where
// the motion began. v0 = J / m = 3 m/s, mu_k g = 2.943 m/s^2: it stops at 0.5 + v0 /
// (mu_k g) = 1.519 s (stop_time counts from the start of the run) after v0^2 / (2 mu_k g) =
// 1.529 m, and creeps nothing after that. Pushed again at 2 s, the stop is that second
// slide's.
TEST(FrictionReference, ABlockPushedFromRestStopsAtTheEndOfItsSlide) {
  const double mu_g = 0.3 * 9.81;
  const Scene once =
      pushed_block("[[impulse]]\nbody = \"block\"\ntime = 0.5\nimpulse = [6.0, 0.0, 0.0]\n");
  const RunRecord run = run_accuracy(ReferenceBackend(), once, once.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const auto value = [&](const Scene& scene, const RunRecord& r, int k) {
    return measure(scene, scene.observes[k], r.trajectory, &r.trajectory.events).value;
  };
  ASSERT_TRUE(value(once, run, 0) && value(once, run, 1) && value(once, run, 2));
  EXPECT_NEAR(*value(once, run, 0), 0.5 + 3.0 / mu_g, kClosedForm);
  EXPECT_NEAR(*value(once, run, 1), 9.0 / (2.0 * mu_g), kClosedForm);
  EXPECT_NEAR(*value(once, run, 2), 0.0, kClosedForm);
  const Scene twice = pushed_block(
      "[[impulse]]\nbody = \"block\"\ntime = 0.5\nimpulse = [6.0, 0.0, 0.0]\n"
      "[[impulse]]\nbody = \"block\"\ntime = 2.0\nimpulse = [-4.0, 0.0, 0.0]\n");
  const RunRecord again = run_accuracy(ReferenceBackend(), twice, twice.report_dt);
  ASSERT_EQ(again.status, RunStatus::Ok) << again.reason;
  ASSERT_TRUE(value(twice, again, 0) && value(twice, again, 1));
  EXPECT_NEAR(*value(twice, again, 0), 2.0 + 2.0 / mu_g, kClosedForm);
  EXPECT_NEAR(*value(twice, again, 1), 4.0 / (2.0 * mu_g), kClosedForm);
}

// A block going down a fixed ramp (a fixed box) onto the level ground: the reference does
// not slide boxes on other bodies, and its reason says that, naming the fixed ramp as fixed
// and the block as the box, whichever order the case lists the two bodies in, with friction
// on the ramp or without.
TEST(FrictionReference, ARampsReasonNamesTheBoxOnAFixedBody) {
  const std::string head = R"(name = "ramp"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
report_dt = 0.01
[ground]
friction_static = 0.6
friction_kinetic = 0.5
)";
  const std::string ramp = R"([[body]]
name = "ramp"
shape = "box"
half_extents = [3.0, 0.1, 0.5]
mass = 1.0
position = [0.0, 1.5, 0.0]
angle = -30.0
fixed = true
)";
  // The block starts a little above the ramp's top face (a start inside is refused).
  const std::string block = R"([[body]]
name = "block"
shape = "box"
half_extents = [0.2, 0.2, 0.2]
mass = 1.0
position = [-1.577, 2.78, 0.0]
angle = -30.0
)";
  const std::string contact = "[[contact]]\nbodies = [\"block\", \"ramp\"]\n";
  const std::string rubbing = contact + "friction = 0.3\n";
  for (const std::string& text : {head + ramp + block + rubbing, head + block + ramp + rubbing,
                                  head + block + ramp + contact}) {
    const RunRecord run = run_accuracy(ReferenceBackend(), test::scene_from(text), 0.01);
    EXPECT_EQ(run.status, RunStatus::Unsupported);
    EXPECT_EQ(run.reason.find("two moving bodies"), std::string::npos) << run.reason;
    EXPECT_NE(run.reason.find("fixed body 'ramp'"), std::string::npos) << run.reason;
    EXPECT_NE(run.reason.find("box 'block'"), std::string::npos) << run.reason;
    // With friction on the ramp, the reason says friction is what the reference lacks.
    const bool rubs = text.find("friction = 0.3") != std::string::npos;
    EXPECT_EQ(run.reason.find("with friction") != std::string::npos, rubs) << run.reason;
  }
}

/// A 1 m box on a ground tilted by `degrees` (towards +x), sent along the slope at `speed`
/// (positive: uphill), with mu_s 0.6 and mu_k 0.5; its velocity written to `digits`
/// significant digits (17: exactly along the slope, as far as doubles go).
Scene block_sent_along_a_slope(double degrees, double speed, int digits = 17) {
  const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  // Uphill is towards -x on a ground whose normal leans towards +x.
  const double ux = -c, uy = s;
  char text[1024];
  std::snprintf(text, sizeof text, R"(name = "sent"
dims = 2
duration = 3.0
sample = 0.05
dt = [0.01]
report_dt = 0.01
[ground]
normal = [%.17g, %.17g, 0.0]
friction_static = 0.6
friction_kinetic = 0.5
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [%.17g, %.17g, 0.0]
angle = %.17g
velocity = [%.*g, %.*g, 0.0]
)",
                s, c, 0.5 * s, 0.5 * c, -degrees, digits, speed * ux, digits, speed * uy);
  return test::scene_from(text);
}

// A block that stops on a slope below atan(mu_s) stays there: sent up 20 degrees at 3 m/s
// it stops after v0 / (g (sin + mu_k cos)); sent down 10 degrees, after v0 / (g (mu_k cos -
// sin)). The reference used to refuse both at the stop ("slides across the force"): the
// rounding of the stopped velocity on a tilted plane left a slide of its own direction.
TEST(FrictionReference, ABlockThatStopsOnASlopeBelowTheThresholdStaysThere) {
  const double g = 9.81;
  for (const auto& [degrees, speed] : {std::pair{20.0, 3.0}, {10.0, -3.0}, {20.0, -3.0}}) {
    const Scene scene = block_sent_along_a_slope(degrees, speed);
    const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << degrees << " " << speed << ": " << run.reason;
    const double a = degrees * M_PI / 180.0;
    const double slowing =
        speed > 0.0 ? g * (std::sin(a) + 0.5 * std::cos(a)) : g * (0.5 * std::cos(a) - std::sin(a));
    const BodyEvents& e = run.trajectory.events.bodies[0];
    ASSERT_TRUE(e.stop_time) << degrees << " " << speed;
    EXPECT_NEAR(*e.stop_time, std::abs(speed) / slowing, kClosedForm) << degrees << " " << speed;
    EXPECT_NEAR((e.stop_position - scene.bodies[0].position).norm(),
                speed * speed / (2.0 * slowing), kClosedForm);
    EXPECT_NEAR((run.trajectory.states.back()[0].position - e.stop_position).norm(), 0.0,
                kClosedForm)
        << degrees << " " << speed << ": it did not stay";
  }
}

// A velocity along the slope written by hand to 14 digits is off the slope by rounding
// (about 1e-15 m/s): the block still starts at rest on the ground, as the reference's own
// resting rule says, and gets the closed form. It used to be "starts moving off the ground"
// (any normal speed but exactly 0), so that a [[sweep]] over ground.normal, whose turned
// velocities carry such rounding, lost the reference at some angles and not others.
TEST(FrictionReference, AVelocityAlongTheSlopeOffItByRoundingStillSlidesFlat) {
  const double g = 9.81;
  for (const double degrees : {10.0, 11.0, 12.0, 25.0}) {
    const Scene scene = block_sent_along_a_slope(degrees, 3.0, 14);
    const double off = scene.bodies[0].velocity.dot(scene.ground->normal);
    ASSERT_NE(off, 0.0) << degrees << ": the velocity is along the slope to the last bit";
    ASSERT_LT(std::abs(off), 1e-13) << degrees;
    const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << degrees << ": " << run.reason;
    const double a = degrees * M_PI / 180.0;
    const BodyEvents& e = run.trajectory.events.bodies[0];
    ASSERT_TRUE(e.stop_time) << degrees;
    EXPECT_NEAR(*e.stop_time, 3.0 / (g * (std::sin(a) + 0.5 * std::cos(a))), 1e-9) << degrees;
  }
}

}  // namespace
}  // namespace bb
