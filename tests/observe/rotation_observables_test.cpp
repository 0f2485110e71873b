// final_angle keeps whole turns: the angle about z is unwrapped at every step from the
// spin, not over the samples, so a ball that turns more than half a turn between two
// samples, or even within one step, is measured with every turn it made.
#include "observe/rotation_observables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "observe/step_observer.hpp"
#include "run/case_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A free ball in 2D without gravity spinning at `spin` rad/s for 2 s, sampled every
/// half second (tens of turns between two samples at 100 rad/s), stepped at 1/30 s.
Scene spinning_ball(double spin) {
  return test::scene_from(test::spinning_ball_case(spin, 30.0));
}

// The course turns a free ball by exactly its spin times the step, the reference to its
// tolerance: both must read spin * 2 s in degrees, whole turns included, at 10 rad/s (a
// third of a radian per step, 5 radians between samples) and at 100 rad/s (3.3 radians per
// step: more than half a turn, where the angle difference alone picks the wrong turn).
TEST(FinalAngle, KeepsEveryTurnOfAFreeSpinOnTheCourseAndTheReference) {
  for (const double spin : {10.0, -10.0, 100.0, -100.0}) {
    const Scene scene = spinning_ball(spin);
    RunOptions options;
    options.backends = {"course/explicit-euler", "course/semi-implicit-euler",
                        "course/velocity-verlet", "course/rk4"};
    options.cost = false;
    const CaseResults results = run_case(scene, Registry::load(), options);
    const double expected = spin * scene.duration * 180.0 / std::numbers::pi;
    int measured = 0;
    std::vector<const RunRecord*> runs = {&results.reference_run};
    for (const RunRecord& run : results.runs) runs.push_back(&run);
    for (const RunRecord* run : runs) {
      ASSERT_EQ(run->status, RunStatus::Ok) << run->backend << ": " << run->reason;
      ASSERT_EQ(run->observables.size(), 1u) << run->backend;
      const auto angle = run->observables[0].measured.value;
      ASSERT_TRUE(angle) << run->backend << ": " << run->observables[0].measured.note;
      // The reference's quaternion is integrated to 1e-10; the course's turn is exact.
      EXPECT_NEAR(*angle, expected, 1e-5) << run->backend << " at " << spin << " rad/s";
      ++measured;
    }
    EXPECT_EQ(measured, 5);
  }
}

// The unwrapped angle travels with each sample: the rotation plot and final_angle read it,
// and it grows steadily for a steady spin, with no jump back by a turn (the sawtooth).
TEST(FinalAngle, TheSampledTurnGrowsWithTheSpinWithoutJumps) {
  const Scene scene = spinning_ball(-100.0);
  RunOptions options;
  options.backends = {"course/rk4"};
  options.cost = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  for (const RunRecord* run : {&results.reference_run, &results.runs.at(0)}) {
    const Trajectory& t = run->trajectory;
    ASSERT_EQ(t.states.size(), 5u) << run->backend;
    const double start = 30.0 * std::numbers::pi / 180.0;
    for (std::size_t j = 0; j < t.states.size(); ++j)
      EXPECT_NEAR(t.states[j][0].turn, start - 100.0 * t.times[j], 1e-7)
          << run->backend << " at " << t.times[j] << " s";
  }
}

/// A ball at rest in 2D without gravity, given a pure couple at 0.5 s (two opposite
/// impulses of `j` N s, 0.5 m above and below its centre) that spins it clockwise at
/// 2 j (r / 2) / (2/5 m r^2) = 10 j rad/s, sampled every `sample` s, stepped at 1/60 s.
Scene kicked_ball(double j, double sample) {
  char text[1024];
  std::snprintf(text, sizeof text, R"(name = "kicked"
dims = 2
duration = 1.0
sample = %.17g
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 2.0, 0.0]
[[impulse]]
body = "ball"
time = 0.5
impulse = [%.17g, 0.0, 0.0]
point = [0.0, 2.5, 0.0]
[[impulse]]
body = "ball"
time = 0.5
impulse = [%.17g, 0.0, 0.0]
point = [0.0, 1.5, 0.0]
[[observe]]
kind = "final_angle"
body = "ball"
)",
                sample, j, -j);
  return test::scene_from(text);
}

// A spin an impulse gives turns the body from the impulse on, in the step it lands in and
// between the reference's samples: at 200 rad/s (3.3 radians per 1/60 s step) and at
// 80 rad/s sampled every 0.1 s, the course and the reference keep every turn of 0.5 s at
// that spin. The mean of the spins before and after the step lost half the step's turn and
// then a whole turn.
TEST(FinalAngle, KeepsEveryTurnOfASpinAnImpulseGives) {
  for (const auto& [j, sample] : {std::pair{20.0, 1.0 / 60.0}, {8.0, 0.1}}) {
    const Scene scene = kicked_ball(j, sample);
    RunOptions options;
    options.backends = {"course/semi-implicit-euler", "course/rk4"};
    options.cost = false;
    const CaseResults results = run_case(scene, Registry::load(), options);
    const double expected = -10.0 * j * 0.5 * 180.0 / std::numbers::pi;
    std::vector<const RunRecord*> runs = {&results.reference_run};
    for (const RunRecord& run : results.runs) runs.push_back(&run);
    for (const RunRecord* run : runs) {
      ASSERT_EQ(run->status, RunStatus::Ok) << run->backend << ": " << run->reason;
      const auto angle = run->observables.at(0).measured.value;
      ASSERT_TRUE(angle) << run->backend << ": " << run->observables[0].measured.note;
      EXPECT_NEAR(*angle, expected, 1e-5) << run->backend << " at " << 10.0 * j << " rad/s";
    }
  }
}

// Where a body's orientation ends a step more than a quarter turn away from where its spin
// says (an orientation update that lags a fast spin), its whole turns are a guess: the
// turn is not counted and final_angle says why, rather than a number marked ok.
TEST(FinalAngle, AStepWhoseTurnTheSpinDoesNotTellIsSaidNotCounted) {
  const Scene scene = kicked_ball(20.0, 1.0 / 60.0);
  StepObserver observer(scene);
  State state(1);
  state[0].orientation = Quat::Identity();
  state[0].angular_velocity = Vec3(0.0, 0.0, -200.0);
  observer.observe(0.0, state);
  // Spinning at -200 rad/s, the body turns by only a third of what its spin says.
  const double h = 1.0 / 60.0, lagging = -200.0 * h / 3.0;
  state[0].orientation = Quat(Eigen::AngleAxisd(lagging, Vec3::UnitZ()));
  observer.observe(h, state);
  ASSERT_TRUE(observer.trace().bodies[0].turn_unclear);
  EXPECT_DOUBLE_EQ(*observer.trace().bodies[0].turn_unclear, h);
  Trajectory t;
  t.times = {0.0, h};
  t.states = {State(1), state};
  t.events = observer.trace();
  const ObservableValue angle = measure_final_angle(scene, scene.observes[0], t, nullptr);
  EXPECT_FALSE(angle.value);
  EXPECT_NE(angle.note.find("cannot be counted"), std::string::npos) << angle.note;
}

}  // namespace
}  // namespace bb
