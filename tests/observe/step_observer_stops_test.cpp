// A stop seen from a run's steps: where the velocity along the ground reaches zero, at the
// end of the body's last motion measured from where it began, with an engine's creep after
// it and a jitter at rest before it no motion of their own.
#include <gtest/gtest.h>

#include "observe/observables.hpp"
#include "observe/step_observer.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

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

}  // namespace
}  // namespace bb
