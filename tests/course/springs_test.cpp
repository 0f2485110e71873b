// Seed section 7 on the course's own spring step: the pair's period converges to the
// closed form as dt halves, explicit Euler's energy grows on an undamped spring while
// semi-implicit Euler's and Verlet's stay bounded, and a damper keeps Euler usable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "course/course_backend.hpp"
#include "metrics/observables.hpp"
#include "reference/closed_form.hpp"
#include "run/accuracy_run.hpp"
#include "scene/motion.hpp"
#include "support/course_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::course;

/// Two 1 kg masses on k = 100 N/m, stretched 0.5 m, no gravity; `damping` in N s/m.
Scene pair(double damping) {
  return test::scene_from(R"(name = "pair"
dims = 2
duration = 10.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667, 0.00833333333333333333, 0.00416666666666666667,
      0.00208333333333333333]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "left"
shape = "point"
mass = 1.0
position = [-0.75, 0.0, 0.0]
[[body]]
name = "right"
shape = "point"
mass = 1.0
position = [0.75, 0.0, 0.0]
[[spring]]
bodies = ["left", "right"]
stiffness = 100.0
rest_length = 1.0
damping = )" + std::to_string(damping) +
                          R"(
[[observe]]
kind = "period"
body = "left"
)");
}

TEST(CourseSprings, PeriodConvergesToTheClosedFormAsDtHalves) {
  const Scene scene = pair(0.0);
  const double exact = closed_form::spring_pair_period(1.0, 1.0, 100.0);
  for (const char* integrator : {"semi-implicit-euler", "velocity-verlet"}) {
    double previous = 1e300;
    for (double dt : scene.dt) {
      const RunRecord run = run_accuracy(course(integrator), scene, dt);
      ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
      const auto period = measure(scene, scene.observes[0], run.trajectory, nullptr).value;
      ASSERT_TRUE(period.has_value()) << integrator;
      const double error = std::abs(*period - exact);
      // Both are second order in the period (semi-implicit Euler's frequency is
      // 2/h asin(h omega / 2)): each halving cuts the error by about four.
      EXPECT_LT(error, previous / 3.0) << integrator << " at dt " << dt;
      previous = error;
    }
    EXPECT_LT(previous, 1e-4 * exact) << integrator;
  }
}

/// Largest energy above the start in the first and in the last quarter of a run (J).
std::pair<double, double> energy_rise(const Scene& scene, const std::string& integrator) {
  const RunRecord run = run_accuracy(course(integrator), scene, scene.report_dt);
  const auto& states = run.trajectory.states;
  const double e0 = total_energy(scene, states.front());
  const std::size_t quarter = states.size() / 4;
  double first = 0.0, last = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const double rise = total_energy(scene, states[i]) - e0;
    if (i < quarter) first = std::max(first, rise);
    if (i >= states.size() - quarter) last = std::max(last, rise);
  }
  return {first, last};
}

TEST(CourseSprings, ExplicitEulerGainsEnergyWhereSemiImplicitEulerAndVerletStayBounded) {
  Scene scene = pair(0.0);
  // At 1/60 s explicit Euler diverges in about a second; over 1 s it must be growing.
  scene.duration = 1.0;
  const auto euler = energy_rise(scene, "explicit-euler");
  EXPECT_GT(euler.second, 10.0 * euler.first);
  scene.duration = 10.0;
  for (const char* bounded : {"semi-implicit-euler", "velocity-verlet"}) {
    const auto [first, last] = energy_rise(scene, bounded);
    EXPECT_LT(last, 1.1 * first + 1e-9) << bounded;
  }
}

TEST(CourseSprings, ADamperKeepsExplicitEulerUsable) {
  // Explicit Euler on x'' = -w^2 x - g x' is stable for dt < g / w^2 (det of its step
  // matrix 1 - g dt + w^2 dt^2 below 1): with c = 20 N s/m, g = c / mu = 40 /s and
  // w^2 = k / mu = 200 /s^2, so 1/60 s < 0.2 s.
  const Scene scene = pair(20.0);
  const RunRecord run = run_accuracy(course("explicit-euler"), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const double e0 = total_energy(scene, run.trajectory.states.front());
  EXPECT_LT(total_energy(scene, run.trajectory.states.back()), 1e-6 * e0);
}

}  // namespace
}  // namespace bb
