// The cost pass's repeats: until the timed total reaches min_seconds and at least
// min_repeats times, fewer once the total passes enough_seconds; each timing gives its
// fastest and slowest repeat beside the median.
#include "run/cost.hpp"

#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "support/slow_backend.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

Timing timing(const CostOptions& options, long steps = 10) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const CourseBackend backend({"course/rk4", "rk4", "mirror", "clamp"});
  return time_steps(backend, scene, scene.report_dt, steps, options);
}

/// Options that repeat for min_repeats, or until the timed total passes enough_seconds.
CostOptions repeat_rule(int min_repeats, double enough_seconds) {
  CostOptions options;
  options.min_seconds = 0.0;
  options.max_wall_seconds = 1e9;
  options.min_repeats = min_repeats;
  options.enough_seconds = enough_seconds;
  return options;
}

TEST(CostRepeats, AtLeastTheMinimumWhileTheTotalIsShort) {
  EXPECT_EQ(timing(repeat_rule(3, 1e9)).repeats, 3);
}

TEST(CostRepeats, OnceWhenOneRepeatIsAlreadyEnough) {
  EXPECT_EQ(timing(repeat_rule(3, 0.0)).repeats, 1);
}

TEST(CostRepeats, TheMaximumCapsARunThatNeverReachesTheTotal) {
  CostOptions options;
  options.min_seconds = 1e9;
  options.max_wall_seconds = 1e9;
  options.max_repeats = 7;
  EXPECT_EQ(timing(options).repeats, 7);
}

// Wall time, building included, stops the repeats once the minimum is done: a run quick to
// step and slow to build is not built thirty times.
TEST(CostRepeats, TheWallTimeBudgetStopsTheRepeatsAfterTheMinimum) {
  CostOptions options;
  options.min_seconds = 1e9;
  options.min_repeats = 4;
  options.max_wall_seconds = 0.0;
  EXPECT_EQ(timing(options).repeats, 4);
  options.max_wall_seconds = 1e9;
  EXPECT_EQ(timing(options).repeats, options.max_repeats);
}

// A repeat that reaches max_seconds_per_repeat stops timing at the end of its block of
// calls; the whole run's time is extrapolated from the calls timed.
TEST(CostRepeats, ALongRunIsTimedOverItsFirstCalls) {
  CostOptions options = repeat_rule(1, 0.0);
  options.max_seconds_per_repeat = 0.0;
  const long steps = 100000;
  const Timing t = timing(options, steps);
  EXPECT_EQ(t.repeats, 1);
  EXPECT_LT(t.calls_timed, steps);
  EXPECT_GT(t.calls_timed, 0);
  EXPECT_GT(t.median_seconds, 0.0);
  options.max_seconds_per_repeat = 1e9;
  EXPECT_EQ(timing(options, 1000).calls_timed, 1000);
}

// A slow step stops a repeat within a few calls of max_seconds_per_repeat: five steps of at
// least a millisecond reach 5 ms, and no block of calls runs past them.
TEST(CostRepeats, ASlowStepStopsARepeatWithinAFewCalls) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const test::SlowBackend backend(0.001);
  CostOptions options = repeat_rule(1, 0.0);
  options.max_seconds_per_repeat = 0.005;
  const Timing t = time_steps(backend, scene, scene.report_dt, 1000, options);
  EXPECT_EQ(t.repeats, 1);
  EXPECT_LE(t.calls_timed, 5);
}

// The seconds timed are every repeat's: at least the fastest repeat's each time (every call
// timed), and a backend that cannot rewind is built once per repeat.
TEST(CostRepeats, TheTimedSecondsAreEveryRepeatsAndEachRepeatBuildsTheScene) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const test::SlowBackend backend(1e-5);
  const Timing t = time_steps(backend, scene, scene.report_dt, 20, repeat_rule(4, 1e9));
  EXPECT_EQ(t.repeats, 4);
  EXPECT_EQ(t.calls_timed, 20);
  EXPECT_GE(t.timed_seconds, 4 * t.min_seconds);
  EXPECT_GE(t.timed_seconds, 4 * 20 * 1e-5);
  EXPECT_EQ(t.builds, 4);
  EXPECT_EQ(backend.starts, 4);
}

TEST(CostRepeats, TheFastestAndSlowestRepeatStandBesideTheMedian) {
  const Timing t = timing(repeat_rule(7, 1e9), 1000);
  EXPECT_EQ(t.repeats, 7);
  EXPECT_GT(t.min_seconds, 0.0);
  EXPECT_LE(t.min_seconds, t.median_seconds);
  EXPECT_LE(t.median_seconds, t.max_seconds);
  const Timing once = timing(repeat_rule(1, 0.0), 1000);
  EXPECT_EQ(once.min_seconds, once.median_seconds);
  EXPECT_EQ(once.max_seconds, once.median_seconds);
}

TEST(CostNoise, TheBusyRuleReadsTheMedianAgainstTheFastestRepeat) {
  EXPECT_TRUE(timed_on_a_busy_machine(Cost{130.0, 0.0, 3, 100.0, 140.0, ""}));
  EXPECT_FALSE(timed_on_a_busy_machine(Cost{120.0, 0.0, 3, 100.0, 900.0, ""}));
  EXPECT_FALSE(timed_on_a_busy_machine(Cost{300.0, 0.0, 2, 100.0, 500.0, ""}));
}

}  // namespace
}  // namespace bb
