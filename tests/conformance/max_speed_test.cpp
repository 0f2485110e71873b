// max_speed, the observable added the registry's way (one file and one line), on every
// backend the registry holds: the largest speed at the samples, wherever in the run it is.
#include <gtest/gtest.h>

#include <cmath>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A ball in free flight for 1 s from `velocity` (a TOML vector), no ground, no air.
Scene thrown(const std::string& velocity) {
  return test::scene_from(R"(name = "thrown"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01, 0.005]
report_dt = 0.01
[[body]]
name = "ball"
radius = 0.1
mass = 1.0
velocity = )" + velocity + R"(
[[observe]]
kind = "max_speed"
body = "ball"
)");
}

/// max_speed/ball on every backend of `scene`, each beside `expected` to `tolerance`
/// (relative; the float engines' own rounding at most 1e-5).
void expect_on_every_backend(const Scene& scene, double expected) {
  BackendSet set = backends_for(scene, test::registry());
  std::vector<const Backend*> backends = set.all;
  backends.push_back(&test::registry().reference());
  ASSERT_GT(backends.size(), 5u);
  for (const Backend* b : backends) {
    SCOPED_TRACE(b->name());
    const RunRecord run = run_accuracy(*b, scene, b->name() == "reference" ? scene.sample : 0.01);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const ObservableValue v = measure(scene, scene.observes[0], run.trajectory, nullptr);
    ASSERT_TRUE(v.value) << v.note;
    const double tolerance = test::single_precision(b->name()) ? 1e-5 : 1e-9;
    EXPECT_NEAR(*v.value, expected, tolerance * expected);
  }
}

TEST(MaxSpeed, IsTheSpeedAtTheStartOfAnUpwardThrow) {
  // 20 m/s up: 20 at t = 0, 10.19 at the end; the largest is the first sample's.
  expect_on_every_backend(thrown("[0.0, 20.0, 0.0]"), 20.0);
}

TEST(MaxSpeed, IsTheSpeedAtTheEndOfAFall) {
  // 3 m/s across, falling: sqrt(9 + (g t)^2) grows to its largest at t = 1 s.
  const double g = 9.81;
  expect_on_every_backend(thrown("[3.0, 0.0, 0.0]"), std::sqrt(9.0 + g * g));
}

}  // namespace
}  // namespace bb
