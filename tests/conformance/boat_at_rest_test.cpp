// drift_angle has no value for a boat at rest, on every backend, and says why: one whose sail
// stands edge-on to the wind (it is pushed not at all: any speed it has is rounding, 8.5e-32
// m/s in Bullet, whose direction gave a drift angle of its own) and one in a dead calm. The
// way it heads, forward_speed, is 0 to rounding. A boat that coasts in the calm still has one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "observe/observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A 200 kg boat heading 30 degrees from x, its sail along its heading, in `wind`, moving at
/// `velocity` at the start.
Scene boat(const std::string& wind, const std::string& velocity = "[0.0, 0.0, 0.0]") {
  return test::scene_from(R"(name = "boat"
dims = 2
duration = 12.0
sample = 0.1
dt = [0.05]
gravity = [0.0, 0.0, 0.0]
[air]
density = 1.2
wind = )" + wind + R"(
[water]
density = 1025.0
[[body]]
name = "boat"
shape = "box"
half_extents = [2.0, 0.75, 0.5]
mass = 200.0
angle = 30.0
velocity = )" + velocity + R"(
[body.sail]
area = 10.0
coefficient = 1.2
angle = 0.0
[body.hull]
forward = 0.05
backward = 0.2
sideways = 2.0
[[observe]]
kind = "drift_angle"
body = "boat"
[[observe]]
kind = "forward_speed"
body = "boat"
)" + test::kEveryIntegrator);
}

class BoatAtRest : public ::testing::TestWithParam<std::string> {
 protected:
  /// The run of this backend on `scene`, or nullopt with skipped_ saying why not.
  std::optional<RunRecord> run(const Scene& scene) {
    std::optional<RunRecord> r = test::run_backend(GetParam(), scene, scene.dt.back(), skipped_);
    if (r) {
      EXPECT_EQ(r->status, RunStatus::Ok) << r->reason;
    }
    return r;
  }
  std::string skipped_;
};

TEST_P(BoatAtRest, HasNoDriftAngleEdgeOnToTheWindOrInACalm) {
  // The wind along the heading, 8 m/s: the sail along it meets it edge-on.
  const double heading = 30.0 * M_PI / 180.0;
  const std::string along = "[" + std::to_string(8.0 * std::cos(heading)) + ", " +
                            std::to_string(8.0 * std::sin(heading)) + ", 0.0]";
  for (const std::string& wind : {along, std::string("[0.0, 0.0, 0.0]")}) {
    const Scene scene = boat(wind);
    const std::optional<RunRecord> r = run(scene);
    if (!r) GTEST_SKIP() << skipped_;
    const ObservableValue drift = measure(scene, scene.observes[0], r->trajectory, nullptr);
    const ObservableValue ahead = measure(scene, scene.observes[1], r->trajectory, nullptr);
    std::printf("%-28s wind %s: drift_angle %s\n", GetParam().c_str(), wind.c_str(),
                drift.value ? std::to_string(*drift.value).c_str() : drift.note.c_str());
    EXPECT_FALSE(drift.value) << "wind " << wind << ": " << *drift.value << " degrees";
    EXPECT_EQ(drift.note.rfind("does not apply: the boat ", 0), 0u) << drift.note;
    ASSERT_TRUE(ahead.value) << ahead.note;
    EXPECT_LT(std::abs(*ahead.value), 1e-9) << "wind " << wind;
  }
}

// Coasting at 1 m/s ahead and 0.5 m/s to port ([0.616, 0.933] at 30 degrees) in the calm, the
// hull's drag slows it but it still moves at the end: its drift angle is measured, atan(across /
// ahead) in (0, 90).
TEST_P(BoatAtRest, ABoatThatCoastsInTheCalmHasADriftAngle) {
  const Scene scene = boat("[0.0, 0.0, 0.0]", "[0.616, 0.933, 0.0]");
  const std::optional<RunRecord> r = run(scene);
  if (!r) GTEST_SKIP() << skipped_;
  const ObservableValue drift = measure(scene, scene.observes[0], r->trajectory, nullptr);
  ASSERT_TRUE(drift.value) << drift.note;
  EXPECT_GT(*drift.value, 0.0);
  EXPECT_LT(*drift.value, 90.0);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, BoatAtRest, ::testing::ValuesIn(test::every_backend()),
                         test::param_test_name);

}  // namespace
}  // namespace bb
