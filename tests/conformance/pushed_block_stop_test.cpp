// stop_time and rest_creep on every backend: a 1 kg block slides on level ground at 7.74 m/s
// while a steady 2 N pushes it on; kinetic friction (mu_k = 0.5) takes 4.905 N, so it stops
// at t = m v0 / (mu_k m g - F) = 2.6644 s, and static friction (mu_s = 0.6, 5.886 N; an
// engine's one coefficient, 4.905 N) holds it there against the push. An engine that then
// creeps (its friction giving way slowly, its soft constraint) has stopped where its slide
// ended: what it moves after is its rest_creep, not a later stop or "never stops".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "observe/observables.hpp"
#include "observe/stop_observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::kG;
constexpr double kMass = 1.0, kSpeed = 7.74, kPush = 2.0, kMuK = 0.5;

/// The block, its stop and its creep observed, over 6 s; `extra` is appended to its stop's
/// [[observe]].
Scene pushed_block(const std::string& extra = "") {
  return test::scene_from(std::string(R"(name = "pushed_block"
dims = 2
duration = 6.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667, 0.00416666666666666667]
report_dt = 0.0166666666666666667
[ground]
friction_static = 0.6
friction_kinetic = 0.5
[[body]]
name = "block"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [0.0, 0.5, 0.0]
velocity = [7.74, 0.0, 0.0]
force = [2.0, 0.0, 0.0]
[[observe]]
kind = "rest_creep"
body = "block"
[[observe]]
kind = "stop_time"
body = "block"
)") + extra + test::kEveryIntegrator);
}

class PushedBlock : public ::testing::TestWithParam<std::string> {};

// The stop within a step of the closed form: a rigid contact's friction stops the block at
// the step after it would have; a soft one (MuJoCo's, whose settings name its contact time
// tau) slows it to rest over its time constant, within two of them more. The creep after
// the stop is measured, and no larger than the rest speed (a thousandth of the fastest the
// block slid) carries it over the rest of the run: slower than that, it is at rest.
TEST_P(PushedBlock, StopsWhereItsSlideEndsAndCreepsAfter) {
  const Scene scene = pushed_block();
  const double closed = kMass * kSpeed / (kMuK * kMass * kG - kPush);
  for (const double dt : scene.dt) {
    std::string skipped;
    const std::optional<RunRecord> run = test::run_backend(GetParam(), scene, dt, skipped);
    if (!run) GTEST_SKIP() << skipped;
    ASSERT_EQ(run->status, RunStatus::Ok) << run->reason;
    const ObservableValue stop = measure(scene, scene.observes[1], run->trajectory, nullptr);
    const ObservableValue creep =
        measure(scene, scene.observes[0], run->trajectory, &run->trajectory.events);
    ASSERT_TRUE(stop.value) << dt << ": " << stop.note;
    ASSERT_TRUE(creep.value) << dt << ": " << creep.note;
    const double tau = test::number_setting(run->engine_settings, "contact_time");
    const double step = GetParam() == "reference" ? 1e-9 : dt;
    const double tolerance = step + (std::isnan(tau) ? 0.0 : 2.0 * tau);
    std::printf("%-28s dt %.5f: stop %.6f s (closed form %.6f), creep after it %.3g m\n",
                GetParam().c_str(), dt, *stop.value, closed, *creep.value);
    EXPECT_NEAR(*stop.value, closed, tolerance) << "dt " << dt;
    EXPECT_LE(*creep.value, kRestShare * kSpeed * (scene.duration - *stop.value + dt))
        << "dt " << dt;
  }
}

// The case's rest speed decides what is rest: set at a tenth of the slide's speed, the stop
// comes where the block slides slower than that, well before the closed form's 2.6644 s.
// Where the sampled speed falls steadily, it lies after the last sample still faster and at
// most a step past the first sample at it or below (the stop is placed on the line through
// the step that came to rest and the one before, at most a step on). MuJoCo's block hops on
// its soft contact (its speed along the ground swings by 0.2 m/s as it slides): it comes to
// rest, sets off and comes to rest again there, and its stop is the last of these.
TEST_P(PushedBlock, TheCasesRestSpeedDecidesWhatIsRest) {
  const double rest = 0.774;
  const Scene early = pushed_block("rest_speed = 0.774\n");
  std::string skipped;
  const double dt = early.dt.back();
  const std::optional<RunRecord> run = test::run_backend(GetParam(), early, dt, skipped);
  if (!run) GTEST_SKIP() << skipped;
  if (GetParam() == "reference") GTEST_SKIP() << "the reference locates its stop exactly";
  ASSERT_EQ(run->status, RunStatus::Ok) << run->reason;
  const ObservableValue stop = measure(early, early.observes[1], run->trajectory, nullptr);
  ASSERT_TRUE(stop.value) << stop.note;
  const double closed = kMass * kSpeed / (kMuK * kMass * kG - kPush);
  EXPECT_LT(*stop.value, closed - 0.1);
  const Trajectory& t = run->trajectory;
  std::size_t j = 0;
  bool steady = true;
  for (; j < t.times.size() && std::abs(t.states[j][0].velocity.x()) > rest; ++j)
    steady = steady && (j == 0 || t.states[j][0].velocity.x() < t.states[j - 1][0].velocity.x());
  ASSERT_GT(j, 0u);
  ASSERT_LT(j, t.times.size());
  if (!steady) return;
  EXPECT_GT(*stop.value, t.times[j - 1]);
  EXPECT_LE(*stop.value, t.times[j] + dt + 1e-9);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, PushedBlock, ::testing::ValuesIn(test::every_backend()),
                         test::param_test_name);

}  // namespace
}  // namespace bb
