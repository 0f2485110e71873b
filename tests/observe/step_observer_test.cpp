// Events found from a fixed-step run's states agree with the reference's located events
// to within what one step can resolve: contacts, apexes, a contact that pushes over many
// steps, and a hit seen only as a push. (Stops: step_observer_stops_test.cpp.)
#include "observe/step_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "course/course_backend.hpp"
#include "observe/observables.hpp"
#include "reference/scene_model.hpp"
#include "study/start_case.hpp"
#include "support/test_support.hpp"
#include "support/thin_panel_case.hpp"

namespace bb {
namespace {

const char* kDrop = R"(name = "drop"
dims = 2
duration = 6.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667, 0.00104166666666666667]
report_dt = 0.0166666666666666667

[ground]
restitution = 0.8

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
)";

EventTrace observed(const Scene& scene, double dt) {
  const CourseBackend backend({"course", "semi-implicit-euler", "mirror", "clamp"});
  auto sim = start_case(backend, scene, dt);
  StepObserver observer(scene);
  State s(scene.bodies.size());
  sim->read(s);
  observer.observe(0.0, s);
  for (long n = 1; n <= std::lround(scene.duration / dt); ++n) {
    sim->step();
    sim->read(s);
    observer.observe(static_cast<double>(n) * dt, s);
  }
  return observer.trace();
}

EventTrace exact(const Scene& scene) {
  SceneModel model(scene);
  HybridIntegrator integrator(model, {}, model.initial_state());
  integrator.advance_to(scene.duration);
  return model.trace();
}

TEST(StepObserver, ContactsAndApexesConvergeToTheReferencesAsDtShrinks) {
  const Scene scene = test::scene_from(kDrop);
  const BodyEvents truth = exact(scene).bodies[0];
  ASSERT_EQ(truth.contact_times.size(), 3u);
  double previous_error = 1e300;
  for (double dt : scene.dt) {
    const BodyEvents seen = observed(scene, dt).bodies[0];
    ASSERT_EQ(seen.contact_times.size(), truth.contact_times.size()) << dt;
    ASSERT_EQ(seen.apex_heights.size(), truth.apex_heights.size()) << dt;
    // The first contact is found at the step that turns the ball around: within a step.
    EXPECT_NEAR(seen.contact_times[0], truth.contact_times[0], 1.01 * dt);
    const double error = std::abs(seen.apex_heights[0] - truth.apex_heights[0]);
    EXPECT_LT(error, previous_error) << dt;
    previous_error = error;
    // `mirror` puts the ball back above the floor within the step: no state shows overlap.
    EXPECT_EQ(seen.max_penetration, 0.0);
  }
  EXPECT_LT(previous_error, 0.05);
}

// A fast small ball and a thin fixed panel (the tunnelling case): the reference's steps are
// bounded so it cannot jump the panel, and it meets it at the closed-form time; at 60 Hz
// the course steps over the panel, and the observer does not mistake the flipped normal
// of a ball that passed through for a bounce; at 1/960 s the course hits it.
TEST(StepObserver, ABallThroughAThinPanelIsNoContactAndTheReferenceCatchesIt) {
  const Scene scene = test::scene_from(R"(name = "tunnelling"
dims = 2
duration = 0.5
sample = 0.0166666666666666667
dt = [0.0166666666666666667, 0.00104166666666666667]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]
)" + test::ball_and_thin_panel("-5.4", "50.0"));
  const BodyEvents truth = exact(scene).bodies[0];
  ASSERT_EQ(truth.contact_times.size(), 1u);
  EXPECT_NEAR(truth.contact_times[0], (5.4 - 0.05 - 0.01) / 50.0, 1e-9);
  EXPECT_NEAR(truth.post_velocity->x(), -25.0, 1e-9);
  // The contact's normal points back from the panel at the ball: it bounced back.
  ASSERT_TRUE(truth.post_normal.has_value());
  EXPECT_NEAR(truth.post_normal->x(), -1.0, 1e-12);
  EXPECT_TRUE(observed(scene, scene.dt[0]).bodies[0].contact_times.empty());
  const BodyEvents fine = observed(scene, scene.dt[1]).bodies[0];
  ASSERT_EQ(fine.contact_times.size(), 1u);
  EXPECT_NEAR(fine.contact_times[0], truth.contact_times[0], 1.01 * scene.dt[1]);
  ASSERT_TRUE(fine.post_normal.has_value());
  EXPECT_NEAR(fine.post_normal->x(), -1.0, 1e-12);
}

// A ball leaving the ground at 5 m/s on an exact parabola, seen every 0.1 s: its apex
// (at 0.5097 s, between two steps) is the peak of the cubic through the steps around it,
// which for a parabola is the parabola itself. The higher of the two steps was 4.6e-4 m
// low: an error of g dt^2 / 8 at most, second order whatever the method.
TEST(StepObserver, FindsAnApexBetweenItsSteps) {
  const Scene scene = test::scene_from(kDrop);
  const double r = scene.bodies[0].radius, g = -scene.gravity.y(), v0 = 5.0, dt = 0.1;
  StepObserver observer(scene);
  State s(1);
  s[0].position = Vec3(0.0, r, 0.0);
  s[0].velocity = Vec3(0.0, -v0, 0.0);
  observer.observe(0.0, s);
  for (int k = 1; k <= 10; ++k) {
    const double t = k * dt;
    s[0].position = Vec3(0.0, r + v0 * t - 0.5 * g * t * t, 0.0);
    s[0].velocity = Vec3(0.0, v0 - g * t, 0.0);
    observer.observe(t, s);
  }
  const BodyEvents& e = observer.trace().bodies[0];
  ASSERT_EQ(e.contact_times.size(), 1u);
  ASSERT_EQ(e.apex_heights.size(), 1u);
  EXPECT_NEAR(e.apex_heights[0], r + v0 * v0 / (2.0 * g), 1e-12);
}

// Two equal balls meet head on and touch softly, as MuJoCo's contact does: a spring pushes
// them apart over many steps, so they stop approaching (both at rest) half-way through the
// contact. The contact is read where it ends, when the spring stops pushing: the post
// velocities are the exchanged ones and the first collision's balance holds the whole
// contact (its energy before is the approach's, after the same: an elastic spring). Read
// at the hit, as a rigid contact is, both would be at rest and half the energy gone.
TEST(StepObserver, ASoftContactIsReadWhenItStopsPushing) {
  const Scene scene = test::scene_from(R"(name = "soft"
dims = 2
duration = 1.0
sample = 0.001
dt = [0.001]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "left"
radius = 0.5
mass = 1.0
position = [-0.6, 0.0, 0.0]
velocity = [1.0, 0.0, 0.0]
[[body]]
name = "right"
radius = 0.5
mass = 1.0
position = [0.6, 0.0, 0.0]
velocity = [-1.0, 0.0, 0.0]
[[contact]]
bodies = ["left", "right"]
restitution = 1.0
)");
  // A stiff elastic spring on the overlap (k / m = 1e4 / s^2), stepped by semi-implicit Euler.
  const double k = 1e4, dt = 1e-4;
  StepObserver observer(scene);
  State s(2);
  for (int i = 0; i < 2; ++i)
    s[i].position = scene.bodies[i].position, s[i].velocity = scene.bodies[i].velocity;
  observer.observe(0.0, s);
  int pushing_steps = 0;
  for (int n = 1; n <= 3000; ++n) {
    const double overlap = 1.0 - (s[1].position.x() - s[0].position.x());
    const double push = overlap > 0.0 ? k * overlap * dt : 0.0;
    pushing_steps += overlap > 0.0;
    s[0].velocity.x() -= push, s[1].velocity.x() += push;
    for (int i = 0; i < 2; ++i) s[i].position += s[i].velocity * dt;
    observer.observe(n * dt, s);
  }
  ASSERT_GT(pushing_steps, 100);  // a contact over many steps
  const EventTrace& trace = observer.trace();
  ASSERT_EQ(trace.bodies[0].contact_times.size(), 1u);
  ASSERT_TRUE(trace.bodies[0].post_velocity && trace.bodies[1].post_velocity);
  // The spring gives back what it took, up to the step's error in its release.
  EXPECT_NEAR(trace.bodies[0].post_velocity->x(), -1.0, 0.02);
  EXPECT_NEAR(trace.bodies[1].post_velocity->x(), 1.0, 0.02);
  ASSERT_TRUE(trace.first_collision);
  EXPECT_NEAR(trace.first_collision->kinetic_energy_before, 1.0, 1e-12);
  EXPECT_NEAR(trace.first_collision->kinetic_energy_after, 1.0, 0.04);
  EXPECT_LT(trace.first_collision->momentum_change.norm(), 1e-12);
  // The hit itself is where they stopped approaching: half-way through the contact.
  const double half = 0.1 + 0.5 * std::numbers::pi / std::sqrt(2.0 * k);
  EXPECT_NEAR(trace.bodies[0].contact_times[0], half, 2e-3);
}

// A hit a backend resolves by pushing the bodies apart over its steps without ever stopping
// their approach (Bullet's ball and plank at 1/120 s: the ball's speed fell from 2 to 0.42
// m/s and it ended inside the plank) has no step where a contact can be timed: every
// contact observable says "not measured:" with what was seen, the overlap and the slowing,
// rather than that nothing touched or no two moving bodies collided.
TEST(StepObserver, AHitSeenOnlyAsAPushIsNotMeasuredAndSaysWhy) {
  const Scene scene = test::scene_from(R"(name = "pushed_apart"
dims = 2
duration = 1.0
sample = 0.01
dt = [0.01]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "left"
radius = 0.5
mass = 1.0
position = [-1.5, 0.0, 0.0]
velocity = [2.0, 0.0, 0.0]
[[body]]
name = "right"
radius = 0.5
mass = 1.0
[[contact]]
bodies = ["left", "right"]
restitution = 1.0
[[observe]]
kind = "momentum_change"
body = "left"
[[observe]]
kind = "post_velocity"
body = "right"
[[observe]]
kind = "contact_time"
body = "left"
)");
  // Overlapping, each step takes a fifth of the approach above 0.05 m/s: it slows towards
  // 0.05 m/s and never stops, the momentum kept.
  const double dt = 0.01;
  StepObserver observer(scene);
  State s(2);
  for (int i = 0; i < 2; ++i)
    s[i].position = scene.bodies[i].position, s[i].velocity = scene.bodies[i].velocity;
  observer.observe(0.0, s);
  for (int n = 1; n <= 100; ++n) {
    const double closing = s[0].velocity.x() - s[1].velocity.x();
    if (s[1].position.x() - s[0].position.x() < 1.0) {
      const double dv = 0.2 * (closing - 0.05);
      s[0].velocity.x() -= 0.5 * dv, s[1].velocity.x() += 0.5 * dv;
    }
    for (int i = 0; i < 2; ++i) s[i].position += s[i].velocity * dt;
    observer.observe(n * dt, s);
  }
  Trajectory run;
  run.times = {0.0, 1.0};
  run.states = {s, s};
  run.events = observer.trace();
  ASSERT_TRUE(run.events.bodies[0].contact_times.empty()) << "a hit was found";
  ASSERT_TRUE(run.events.bodies[0].unresolved_contact);
  EXPECT_EQ(run.events.bodies[0].unresolved_contact->other, 1);
  EXPECT_NEAR(run.events.bodies[0].unresolved_contact->approach_before, 2.0, 1e-12);
  EXPECT_GT(run.events.bodies[0].unresolved_contact->approach_least, 0.05);
  EXPECT_LT(run.events.bodies[0].unresolved_contact->approach_least, 0.06);
  for (const Observe& o : scene.observes) {
    const ObservableValue v = measure(scene, o, run, nullptr);
    EXPECT_FALSE(v.value) << o.name;
    EXPECT_EQ(v.note.rfind("not measured: from t = ", 0), 0u) << o.name << ": " << v.note;
    EXPECT_NE(v.note.find("of 'left' and 'right' (overlapping by up to") == std::string::npos &&
                  v.note.find("of 'right' and 'left' (overlapping by up to") == std::string::npos,
              true)
        << v.note;
    EXPECT_NE(v.note.find("slowed from 2 to 0.05"), std::string::npos) << v.note;
  }
}

}  // namespace
}  // namespace bb
