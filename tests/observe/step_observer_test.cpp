// Events found from a fixed-step run's states agree with the reference's located events
// to within what one step can resolve.
#include "observe/step_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "course/course_backend.hpp"
#include "observe/observables.hpp"
#include "reference/scene_model.hpp"
#include "support/test_support.hpp"

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
  auto sim = backend.start(scene, dt);
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
[[body]]
name = "ball"
radius = 0.05
mass = 0.05
position = [-5.4, 1.0, 0.0]
velocity = [50.0, 0.0, 0.0]
[[body]]
name = "panel"
shape = "box"
half_extents = [0.01, 1.0, 1.0]
mass = 1.0
fixed = true
position = [0.0, 1.0, 0.0]
[[contact]]
bodies = ["ball", "panel"]
restitution = 0.5
)");
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

// A stop seen from the steps: a velocity along the ground that turns back between two
// steps crossed zero where the straight line between them does; one that reaches zero
// stopped at that step; a body at rest at the start that stays there stopped at t = 0,
// and one that starts to slide from rest has not stopped yet.
TEST(StepObserver, StopsAreWhereTheVelocityAlongTheGroundReachesZero) {
  const Scene scene = test::scene_from(
      test::level_ground_case("stops", "friction_static = 0.5\n") +
      test::resting_box("turns", 0.0) + test::resting_box("halts", 5.0) +
      test::resting_box("held", 10.0) + test::resting_box("slips", 15.0) + R"([[observe]]
kind = "stop_time"
body = "turns"
[[observe]]
kind = "stop_time"
body = "halts"
[[observe]]
kind = "stop_time"
body = "held"
[[observe]]
kind = "stop_time"
body = "slips"
)");
  StepObserver observer(scene);
  // Velocities along x at t = 0, 0.1, 0.2, 0.3 s (a vertical part is not sliding).
  const double turns[] = {0.3, 0.1, -0.1, -0.3}, halts[] = {0.2, 0.1, 0.0, 0.0},
               held[] = {0.0, 0.0, 0.0, 0.0}, slips[] = {0.0, 0.5, 1.0, 1.5};
  State s(4);
  for (int k = 0; k < 4; ++k) {
    const double t = 0.1 * k;
    s[0].velocity = {turns[k], -1.0, 0.0}, s[0].position = {t, 0.5, 0.0};
    s[1].velocity = {halts[k], 0.0, 0.0}, s[2].velocity = {held[k], 0.0, 0.0};
    s[3].velocity = {slips[k], 0.0, 0.0};
    observer.observe(t, s);
  }
  const EventTrace& e = observer.trace();
  ASSERT_TRUE(e.bodies[0].stop_time && e.bodies[1].stop_time && e.bodies[2].stop_time);
  EXPECT_NEAR(*e.bodies[0].stop_time, 0.15, 1e-15);
  EXPECT_NEAR(e.bodies[0].stop_position.x(), 0.15, 1e-15);
  EXPECT_NEAR(*e.bodies[1].stop_time, 0.2, 1e-15);
  EXPECT_EQ(*e.bodies[2].stop_time, 0.0);
  EXPECT_FALSE(e.bodies[3].stop_time);
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

// A stop is the end of the body's last motion along the ground, which begins where it
// leaves a rest (or at the start): a block at rest that is pushed stops where that slide
// ends, not at t = 0; one pushed twice stops where the second slide ends; one that rests
// for a few steps and then slides to the end never stops; a wobble far smaller than the
// slide after a stop, or a jitter at rest before a push, is no motion of its own.
TEST(StepObserver, AStopIsTheEndOfTheLastMotionMeasuredFromWhereItBegan) {
  const Scene scene =
      test::scene_from(test::level_ground_case("stops", "friction_static = 0.5\n") +
                       test::resting_box("pushed", 0.0) + test::resting_box("twice", 5.0) +
                       test::resting_box("late", 10.0) + test::resting_box("wobbles", 15.0) +
                       test::resting_box("jitters", 20.0) + test::resting_box("nudged", 25.0) +
                       test::resting_box("against", 30.0) +
                       R"([[observe]]
kind = "stop_time"
body = "pushed"
[[observe]]
kind = "stop_time"
body = "twice"
[[observe]]
kind = "stop_time"
body = "late"
[[observe]]
kind = "stop_time"
body = "wobbles"
[[observe]]
kind = "stop_time"
body = "jitters"
[[observe]]
kind = "stop_time"
body = "nudged"
[[observe]]
kind = "stop_time"
body = "against"
)");
  StepObserver observer(scene);
  // Velocities along x at t = 0, 0.1, ..., 1.0 s.
  const std::vector<std::vector<double>> v = {
      {0.0, 0.0, 0.0, 0.0, 0.3, 0.2, 0.1, 0.0, 0.0, 0.0, 0.0},
      {0.3, 0.2, 0.1, 0.0, 0.0, 0.0, 0.4, 0.2, 0.0, 0.0, 0.0},
      {0.0, 0.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0},
      {1.0, 0.5, 0.0, 0.0, 0.0, 1e-4, 0.0, 0.0, 0.0, 0.0, 0.0},
      {0.0, 2e-6, -2e-6, 2e-6, 0.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0},
      {0.0, 5e-3, 0.0, 0.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0},
      {0.0, -1e-5, -1e-5, -1e-5, 0.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0}};
  const std::size_t n = v.size();
  State s(n);
  for (std::size_t i = 0; i < n; ++i) s[i].position = scene.bodies[i].position;
  for (std::size_t k = 0; k < v[0].size(); ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      // Each step moves a body by the mean of the velocities at its ends.
      if (k > 0) s[i].position.x() += 0.05 * (v[i][k - 1] + v[i][k]);
      s[i].velocity = {v[i][k], 0.0, 0.0};
    }
    observer.observe(0.1 * static_cast<double>(k), s);
  }
  const EventTrace e = observer.trace();
  ASSERT_TRUE(e.bodies[0].stop_time && e.bodies[1].stop_time && e.bodies[3].stop_time);
  // Pushed between 0.3 and 0.4 s, stopped at 0.7 s after 0.015 + 0.025 + 0.015 + 0.005 m.
  EXPECT_NEAR(*e.bodies[0].stop_time, 0.7, 1e-15);
  EXPECT_NEAR((e.bodies[0].stop_position - e.bodies[0].motion_start).x(), 0.06, 1e-15);
  EXPECT_NEAR(e.bodies[0].motion_start.x(), 0.0, 1e-15);
  // The second slide: from 0.5 s, stopped at 0.8 s after 0.02 + 0.03 + 0.01 m.
  EXPECT_NEAR(*e.bodies[1].stop_time, 0.8, 1e-15);
  EXPECT_NEAR((e.bodies[1].stop_position - e.bodies[1].motion_start).x(), 0.06, 1e-15);
  // Still sliding at the end: no stop.
  EXPECT_FALSE(e.bodies[2].stop_time);
  // The wobble at a ten-thousandth of the slide's speed is no motion: the stop stays at 0.2 s.
  EXPECT_NEAR(*e.bodies[3].stop_time, 0.2, 1e-15);
  // A float engine's jitter at rest (above a millionth of |g| dt, turning back and forth)
  // is no motion either; the push after it is: from 0.3 s to its stop at 0.7 s.
  ASSERT_TRUE(e.bodies[4].stop_time);
  EXPECT_NEAR(*e.bodies[4].stop_time, 0.7, 1e-15);
  EXPECT_NEAR(e.bodies[4].motion_start.x(), 20.0 + 0.05 * 2e-6, 1e-12);
  // A jitter above the quiet level that comes to rest one step before a push does not hide
  // the push: the slide from 0.2 s stops at 0.6 s after 0.025 + 0.04 + 0.02 + 0.005 m.
  ASSERT_TRUE(e.bodies[5].stop_time);
  EXPECT_NEAR(*e.bodies[5].stop_time, 0.6, 1e-15);
  EXPECT_NEAR((e.bodies[5].stop_position - e.bodies[5].motion_start).x(), 0.09, 1e-12);
  // A push against the direction of a creep below the quiet level is no turning back:
  // bullet-float's block stopped "at the push" this way. It stops where the slide ends.
  ASSERT_TRUE(e.bodies[6].stop_time);
  EXPECT_NEAR(*e.bodies[6].stop_time, 0.7, 1e-15);
}

// An engine's creep after its stop is no motion: a slide that slows by 1 m/s^2 and, where
// it would stop at 0.4 s, creeps on at 1e-5 m/s (ODE's friction gives way about that slowly)
// stops where the slide's speed reaches zero, 0.4 s, and the creep is its rest_creep. A
// case that sets the rest speed below the creep (1e-6 m/s) counts the creep as motion: the
// body never stops then, and the note says at which rest speed.
TEST(StepObserver, AnEnginesCreepAfterItsStopIsNotMotion) {
  const Scene scene =
      test::scene_from(test::level_ground_case("creep", "friction_static = 0.5\n") +
                       test::resting_box("creeps", 0.0) + test::resting_box("strict", 5.0) +
                       R"([[observe]]
kind = "stop_time"
body = "creeps"
[[observe]]
kind = "stop_time"
body = "strict"
rest_speed = 1e-6
)");
  StepObserver observer(scene);
  State s(2);
  for (std::size_t i = 0; i < 2; ++i) s[i].position = scene.bodies[i].position;
  // Velocities along x at t = 0, 0.1, ..., 1.0 s: the slide, then the creep.
  for (int k = 0; k <= 10; ++k) {
    const double v = k < 4 ? 0.4 - 0.1 * k : 1e-5;
    for (BodyState& b : s) {
      if (k > 0) b.position.x() += 0.05 * (b.velocity.x() + v);
      b.velocity = {v, 0.0, 0.0};
    }
    observer.observe(0.1 * k, s);
  }
  const EventTrace& e = observer.trace();
  ASSERT_TRUE(e.bodies[0].stop_time) << "the creep was counted as motion";
  // Where the line through the last two steps (0.1 m/s, then 1e-5) reaches zero.
  EXPECT_NEAR(*e.bodies[0].stop_time, 0.4, 2e-5);
  EXPECT_FALSE(e.bodies[1].stop_time);
  Trajectory run;
  run.times = {0.0, 1.0};
  run.states = {s, s};
  run.events = e;
  const ObservableValue strict = measure(scene, scene.observes[1], run, nullptr);
  EXPECT_FALSE(strict.value);
  EXPECT_NE(strict.note.find("rest speed (1e-06 m/s, the case's 'rest_speed')"), std::string::npos)
      << strict.note;
}

// A slide that eases to a stop (the course's clamp: the step that would reverse it ends at
// rest) has no creep: its stop is where it came to rest, not a place on the line through its
// last two steps past that, which would count the slide's last step below the rest speed
// as creep (2.9e-6 m on friction_materials' lubricated steel, against a gate of 1e-12).
TEST(StepObserver, ASlideThatEasesToAStopHasNoCreep) {
  const Scene scene = test::scene_from(test::level_ground_case("eases", "friction_static = 0.5\n") +
                                       test::resting_box("block", 0.0) + R"([[observe]]
kind = "stop_time"
body = "block"
)");
  StepObserver observer(scene);
  State s(1);
  s[0].position = scene.bodies[0].position;
  // Velocities along x at t = 0, 0.1, ..., 0.6 s, each step's position moved by its new
  // velocity (semi-implicit): slower than the rest speed (4e-4 m/s) at 0.4 s, 0 from 0.5 s.
  const double speeds[] = {0.4, 0.3, 0.2, 0.1, 3e-4, 0.0, 0.0};
  for (int k = 0; k <= 6; ++k) {
    s[0].velocity = {speeds[k], 0.0, 0.0};
    if (k > 0) s[0].position.x() += 0.1 * speeds[k];
    observer.observe(0.1 * k, s);
  }
  const BodyEvents& e = observer.trace().bodies[0];
  ASSERT_TRUE(e.stop_time);
  EXPECT_GT(*e.stop_time, 0.4);
  EXPECT_LE(*e.stop_time, 0.5);
  EXPECT_EQ(e.stop_position, s[0].position) << "the stop overshoots where the block rests";
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
