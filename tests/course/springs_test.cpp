// Seed section 7 on the course's own spring step: the pair's period converges to the
// closed form as dt halves, explicit Euler's energy grows on an undamped spring while
// semi-implicit Euler's and Verlet's stay bounded, and a damper keeps Euler usable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "observe/observables.hpp"
#include "physics/energy.hpp"
#include "reference/closed_form.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
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

namespace bb {
namespace {

// A damped chain of three masses, one end pushed across the chain: its largest stretch is
// a peak that falls between the steps. RK4 measured at every step (and between them, on
// the cubic through its steps' values and rates) converges on the reference's at RK4's
// own order: each halving of dt divides the error by 2^4, within a factor 2^0.5. Read at
// the samples instead, the reference's value was low by a fixed amount and the error
// stopped shrinking.
TEST(CourseSprings, Rk4sLargestStretchConvergesAtOrderFour) {
  const Scene scene = test::scene_from(R"(name = "chain"
dims = 2
duration = 2.0
sample = 0.1
dt = [0.05, 0.025, 0.0125, 0.00625]
report_dt = 0.025
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "a"
shape = "point"
mass = 1.0
position = [0.0, 0.0, 0.0]
[[body]]
name = "b"
shape = "point"
mass = 1.0
position = [1.0, 0.0, 0.0]
[[body]]
name = "c"
shape = "point"
mass = 1.0
position = [2.0, 0.0, 0.0]
velocity = [1.5, 0.7, 0.0]
[[spring]]
bodies = ["a", "b"]
stiffness = 30.0
damping = 0.5
[[spring]]
bodies = ["b", "c"]
stiffness = 30.0
damping = 0.5
[[observe]]
kind = "max_stretch"
)");
  const RunRecord reference = run_accuracy(ReferenceBackend(), scene, scene.sample);
  ASSERT_EQ(reference.status, RunStatus::Ok) << reference.reason;
  const auto value = [&](const RunRecord& run) {
    const ObservableValue v = measure(scene, scene.observes[0], run.trajectory, nullptr);
    EXPECT_TRUE(v.value.has_value()) << v.note;
    return v.value.value_or(0.0);
  };
  const double truth = value(reference);
  std::vector<double> errors;
  for (double dt : scene.dt) {
    const RunRecord run = run_accuracy(course("rk4"), scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    errors.push_back(std::abs(value(run) - truth));
    std::printf("dt %g: max_stretch %.12g, error %.3g\n", dt, value(run), errors.back());
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    // Ten times the reference's own error (1e-10) or more: the slope is the method's.
    ASSERT_GT(errors[i], 1e-9) << i;
    EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 4.0, 0.5) << "dt " << scene.dt[i];
  }
}

}  // namespace
}  // namespace bb
