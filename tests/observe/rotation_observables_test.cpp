// final_angle keeps whole turns: the angle about z is unwrapped at every step from the
// spin, not over the samples, so a ball that turns more than half a turn between two
// samples, or even within one step, is measured with every turn it made.
#include "observe/rotation_observables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

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

}  // namespace
}  // namespace bb
