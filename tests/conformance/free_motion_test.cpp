// Properties of motion written once and run over every backend there is: the reference,
// every course integrator and every engine backend of the catalogue. A backend that cannot
// run a scene is skipped with the reason its description gives; one whose plugin was not
// built, with that. A new engine is tested here with no edit to this file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/motion.hpp"
#include "observe/observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

const char* const kCourse = test::kEveryIntegrator;

class Conformance : public ::testing::TestWithParam<std::string> {
 protected:
  /// The run of this backend on `scene` at its finest step, or a skip that says why not.
  /// Empty when skipped.
  std::optional<RunRecord> run(const Scene& scene) {
    return test::run_backend(GetParam(), scene, scene.dt.back(), skipped_);
  }

  /// Rounding allowed, relative: the float engines' own, else a double's over a run.
  double tolerance() const { return test::single_precision(GetParam()) ? 2e-5 : 1e-9; }

  std::string skipped_;
};

/// The final velocity of body `body` of `record`.
Vec3 final_velocity(const RunRecord& record, int body) {
  return record.trajectory.states.back()[static_cast<std::size_t>(body)].velocity;
}

TEST_P(Conformance, AConstantForceChangesTheVelocityByForceOverMassTimesTime) {
  // 2 kg pushed by 3 N along x under gravity for 1 s: every method integrates a constant
  // acceleration's velocity exactly, whatever its order.
  const Scene scene = test::scene_from(std::string(R"(name = "pushed"
dims = 2
duration = 1.0
sample = 0.25
dt = [0.01]
[[body]]
name = "ball"
radius = 0.1
mass = 2.0
velocity = [1.0, 4.0, 0.0]
force = [3.0, 0.0, 0.0]
)") + kCourse);
  const std::optional<RunRecord> record = run(scene);
  if (!record) GTEST_SKIP() << skipped_;
  ASSERT_EQ(record->status, RunStatus::Ok) << record->reason;
  const Vec3 v = final_velocity(*record, 0);
  EXPECT_NEAR(v.x(), 1.0 + 1.5, tolerance() * 2.5);
  EXPECT_NEAR(v.y(), 4.0 - 9.81, tolerance() * 5.81);
}

TEST_P(Conformance, AnImpulseChangesTheVelocityByImpulseOverMass) {
  // 4 N s on 2 kg at 0.5 s, no gravity: +2 m/s from then on.
  const Scene scene = test::scene_from(std::string(R"(name = "kicked"
dims = 2
duration = 1.0
sample = 0.25
dt = [0.01]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "ball"
radius = 0.1
mass = 2.0
velocity = [1.0, 0.0, 0.0]
[[impulse]]
body = "ball"
time = 0.5
impulse = [4.0, 0.0, 0.0]
)") + kCourse);
  const std::optional<RunRecord> record = run(scene);
  if (!record) GTEST_SKIP() << skipped_;
  ASSERT_EQ(record->status, RunStatus::Ok) << record->reason;
  EXPECT_NEAR(final_velocity(*record, 0).x(), 3.0, tolerance() * 3.0);
  // The sample at the push's own time is the state before it.
  EXPECT_NEAR(record->trajectory.states[2][0].velocity.x(), 1.0, tolerance());
}

TEST_P(Conformance, TwoBallsThatMeetKeepTheirMomentum) {
  // 1 kg at 2 m/s meets 3 kg at rest, head on, no gravity; whatever the contact model, the
  // total momentum (2 kg m/s along x) stays, and the balls are apart at the end.
  const Scene scene = test::scene_from(std::string(R"(name = "meet"
dims = 2
duration = 1.0
sample = 0.25
dt = [0.005]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "light"
radius = 0.1
mass = 1.0
position = [-0.5, 0.0, 0.0]
velocity = [2.0, 0.0, 0.0]
[[body]]
name = "heavy"
radius = 0.1
mass = 3.0
position = [0.0, 0.0, 0.0]
[[contact]]
bodies = ["light", "heavy"]
restitution = 0.8
)") + kCourse);
  const std::optional<RunRecord> record = run(scene);
  if (!record) GTEST_SKIP() << skipped_;
  ASSERT_EQ(record->status, RunStatus::Ok) << record->reason;
  const Vec3 light = final_velocity(*record, 0);
  const Vec3 heavy = final_velocity(*record, 1);
  EXPECT_NEAR(light.x() + 3.0 * heavy.x(), 2.0, std::max(tolerance(), 1e-9) * 2.0);
  EXPECT_NEAR(light.y() + 3.0 * heavy.y(), 0.0, 1e-9);
  EXPECT_GT(heavy.x(), light.x()) << "the balls still approach each other at the end";
}

TEST_P(Conformance, TwoMassesOnASpringKeepTheirMomentumAndSwing) {
  // 1 kg and 3 kg on a 100 N/m spring stretched by 0.1 m, no gravity: the spring's forces are
  // equal and opposite whatever builds them (a force, a joint, a tendon), so the momentum
  // stays 0; the pair swings with T = 2 pi sqrt(mu / k), mu = 0.75 kg (0.544 s), within 10 %
  // (a soft joint runs slow: the engine pages show by how much).
  const Scene scene = test::scene_from(std::string(R"(name = "pair"
dims = 2
duration = 3.0
sample = 0.00416666666666666667
dt = [0.00416666666666666667]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "light"
shape = "point"
mass = 1.0
position = [-0.825, 0.0, 0.0]
[[body]]
name = "heavy"
shape = "point"
mass = 3.0
position = [0.275, 0.0, 0.0]
[[spring]]
bodies = ["light", "heavy"]
stiffness = 100.0
rest_length = 1.0
[[observe]]
kind = "period"
body = "light"
)") + kCourse);
  const std::optional<RunRecord> record = run(scene);
  if (!record) GTEST_SKIP() << skipped_;
  ASSERT_EQ(record->status, RunStatus::Ok) << record->reason;
  double worst = 0.0;
  for (const State& s : record->trajectory.states)
    worst = std::max(worst, (s[0].velocity + 3.0 * s[1].velocity).norm());
  EXPECT_LT(worst, std::max(tolerance(), 1e-9) * 10.0);
  const auto period = measure(scene, scene.observes[0], record->trajectory, nullptr).value;
  ASSERT_TRUE(period);
  const double closed = 2.0 * std::numbers::pi * std::sqrt(0.75 / 100.0);
  EXPECT_NEAR(*period, closed, 0.1 * closed);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, Conformance, ::testing::ValuesIn(test::every_backend()),
                         test::param_test_name);

}  // namespace
}  // namespace bb
