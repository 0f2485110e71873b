// time_above: the time a body's centre spends above a level, from the level's crossings. On
// a throw without a floor it has a closed form, 2 sqrt(2 (h_apex - level) / g); the
// reference locates the crossings as events, exact to its event tolerance, and a stepped
// backend's value, from crossings placed between its steps, comes nearer as its step shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "observe/observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

constexpr double kG = 9.81;

/// A ball thrown up at `speed` from the origin, no ground, no air, for `duration` s,
/// observed above `level`.
Scene throw_above(double speed, double level, double duration) {
  return test::scene_from(R"(name = "thrown"
dims = 2
duration = )" + std::to_string(duration) +
                          R"(
sample = 0.1
dt = [0.01, 0.005, 0.0025]
report_dt = 0.01
[[body]]
name = "ball"
radius = 0.1
mass = 1.0
velocity = [0.0, )" + std::to_string(speed) +
                          R"(, 0.0]
[[observe]]
kind = "time_above"
body = "ball"
level = )" + std::to_string(level) +
                          R"(
[course]
integrators = ["semi-implicit-euler"]
)");
}

/// The closed form: above the level from crossing it going up to crossing it going down.
double time_above(double speed, double level) {
  const double apex = speed * speed / (2.0 * kG);
  return apex > level ? 2.0 * std::sqrt(2.0 * (apex - level) / kG) : 0.0;
}

/// The run's time_above of `backend` at `dt` (the reference at the samples).
double measured(const std::string& backend, const Scene& scene, double dt) {
  std::string skipped;
  const std::optional<RunRecord> run = test::run_backend(backend, scene, dt, skipped);
  if (!run) ADD_FAILURE() << skipped;
  if (!run) return 0.0;
  EXPECT_EQ(run->status, RunStatus::Ok) << run->reason;
  const ObservableValue v = measure(scene, scene.observes[0], run->trajectory, nullptr);
  EXPECT_TRUE(v.value) << v.note;
  return v.value.value_or(0.0);
}

TEST(TimeAbove, TheReferenceMeetsTheClosedFormToItsEventTolerance) {
  // Levels below the apex at several heights; each crossing is located to 1e-12 s.
  for (const double level : {0.5, 1.0, 3.0, 5.0}) {
    SCOPED_TRACE(level);
    const Scene scene = throw_above(10.0, level, 2.5);
    const double value = measured("reference", scene, scene.sample);
    EXPECT_NEAR(value, time_above(10.0, level), 1e-9);
  }
}

TEST(TimeAbove, IsTheWholeRunAboveALevelNeverCrossedAndNoneBelowOne) {
  // Starting 0 m high: below a level of -1 m throughout the 1 s flight (it ends at 5.1 m up),
  // below a level of 10 m throughout (the apex is 5.1 m).
  const Scene low = throw_above(10.0, -1.0, 1.0), high = throw_above(10.0, 10.0, 1.0);
  EXPECT_NEAR(measured("reference", low, low.sample), 1.0, 1e-12);
  EXPECT_EQ(measured("reference", high, high.sample), 0.0);
}

TEST(TimeAbove, ASteppedBackendsErrorShrinksWithItsStep) {
  // Semi-implicit Euler is first order: its crossings are off by about g t dt / (2 v), so
  // halving dt about halves its error.
  const Scene scene = throw_above(10.0, 1.0, 2.5);
  double last = 0.0;
  for (const double dt : scene.dt) {
    SCOPED_TRACE(dt);
    const double error =
        std::abs(measured("course/semi-implicit-euler", scene, dt) - time_above(10.0, 1.0));
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, 2.0 * dt);
    if (last > 0.0) {
      EXPECT_LT(error, 0.7 * last);
      EXPECT_GT(error, 0.3 * last);
    }
    last = error;
  }
}

TEST(TimeAbove, SaysSoInACaseWithoutGravity) {
  Scene scene = throw_above(10.0, 1.0, 1.0);
  scene.gravity = Vec3::Zero();
  std::string skipped;
  const std::optional<RunRecord> run = test::run_backend("reference", scene, scene.sample, skipped);
  ASSERT_TRUE(run) << skipped;
  const ObservableValue v = measure(scene, scene.observes[0], run->trajectory, nullptr);
  EXPECT_FALSE(v.value);
  EXPECT_NE(v.note.find("no gravity"), std::string::npos) << v.note;
}

}  // namespace
}  // namespace bb
