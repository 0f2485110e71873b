// The course's friction (seed section 6): the naive rule overshoots zero and crawls, the
// two fixes stop the block; the rules' forces as properties of one step.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "course/course_backend.hpp"
#include "course/friction_rules.hpp"
#include "metrics/stop_observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "scene/load_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using course::Coulomb;
using course::FrictionRule;
using Eigen::Vector3d;

RunRecord run_rule(const Scene& scene, const std::string& rule, const std::string& integrator) {
  const CourseBackend backend({"course/" + integrator + "+" + rule, integrator, "clamp", rule});
  return run_accuracy(backend, scene, scene.report_dt);
}

/// `kind`/`body` of `run`, measured against the reference's events.
std::optional<double> observed(const Scene& scene, const RunRecord& run, const RunRecord& ref,
                               const std::string& kind, const std::string& body) {
  const Observe o{kind, scene.body_index(body), 0, 0, kind + "/" + body};
  return measure(scene, o, run.trajectory, &ref.trajectory.events).value;
}

// The seed's demo: after the stop, naive crawls (it carries the velocity past zero, and
// the next step's friction throws it back); clamp does not move at all, low-speed no more
// than rounding. For each block, each Euler.
TEST(CourseFriction, NaiveCreepsAfterTheStopAndBothFixesDoNot) {
  const Scene scene = load_case(test::source_path("cases/sliding_block.toml"));
  const RunRecord ref = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(ref.status, RunStatus::Ok) << ref.reason;
  for (const std::string integrator : {"explicit-euler", "semi-implicit-euler"})
    for (const std::string body : {"slow", "medium", "fast"}) {
      const auto naive =
          observed(scene, run_rule(scene, "naive", integrator), ref, "rest_creep", body);
      const auto clamp =
          observed(scene, run_rule(scene, "clamp", integrator), ref, "rest_creep", body);
      const auto low =
          observed(scene, run_rule(scene, "low-speed", integrator), ref, "rest_creep", body);
      ASSERT_TRUE(naive && clamp && low) << integrator << " " << body;
      std::printf("%s %s: creep naive %.4g m, clamp %.3g m, low-speed %.3g m\n", integrator.c_str(),
                  body.c_str(), *naive, *clamp, *low);
      // A crawl of millimetres to centimetres over the rest of the run...
      EXPECT_GT(*naive, 1e-3) << integrator << " " << body;
      // ...where clamp stands still and low-speed's one capped step leaves rounding.
      EXPECT_EQ(*clamp, 0.0) << integrator << " " << body;
      EXPECT_LT(*low, 1e-12) << integrator << " " << body;
    }
}

// Semi-implicit Euler with the low-speed cap gives the discrete answer for a 1 kg
// box at 5 m/s with mu = 0.5 at 1/60 s: the steps v -= mu g dt, x += v dt, until the one
// that would reverse v, which the cap turns into v = 0 (step 62, 1.0333 s, 2.50685 m).
TEST(CourseFriction, LowSpeedEndsTheSlideOnTheStepThatWouldReverseIt) {
  const Scene scene = load_case(test::source_path("cases/sliding_block.toml"));
  const RunRecord run = run_rule(scene, "low-speed", "semi-implicit-euler");
  const int medium = scene.body_index("medium");
  const double dt = scene.report_dt, a = 0.5 * 9.81 * dt;
  double v = 5.0, x = 0.0;
  int steps = 0;
  while (v - a > 0.0) v -= a, x += v * dt, ++steps;
  // The capped step brings v to zero: x does not change on it.
  ASSERT_TRUE(run.trajectory.events.bodies[medium].stop_time);
  EXPECT_NEAR(*run.trajectory.events.bodies[medium].stop_time, (steps + 1) * dt, 1e-12);
  const Vector3d start = scene.bodies[medium].position;
  EXPECT_NEAR((run.trajectory.events.bodies[medium].stop_position - start).x(), x, 1e-12);
  EXPECT_NEAR(x, 2.50685, 1e-5);
}

// On a slope that holds (tan 28 = 0.53 below mu_s = 0.6, above mu_k = 0.5), every rule
// holds the block: it starts at rest, where static friction takes the slope's pull.
TEST(CourseFriction, EveryRuleHoldsTheBlockOnSlopeHold) {
  const Scene scene = load_case(test::source_path("cases/slope_hold.toml"));
  for (const std::string rule : {"naive", "clamp", "low-speed"}) {
    const RunRecord run = run_rule(scene, rule, "semi-implicit-euler");
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const Vec3 moved =
        run.trajectory.states.back()[0].position - run.trajectory.states.front()[0].position;
    EXPECT_LT(moved.norm(), 1e-15) << rule;
  }
}

// One step's friction, as a property over random states: kinetic friction opposes the
// sliding velocity with mu_k N; at rest, static friction holds up to mu_s N exactly and
// lets go just beyond; the low-speed cap never lets one explicit step reverse the velocity.
TEST(CourseFriction, OneStepsForceObeysCoulomb) {
  const Coulomb c{0.6, 0.5};
  const Vector3d n = Vector3d(0.3, 1.0, -0.2).normalized();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<> u(-3.0, 3.0);
  const double dt = 1.0 / 60.0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d g(u(rng), -9.81, u(rng));
    const Vector3d v = course::tangential(Vector3d(u(rng), u(rng), u(rng)), n);
    const double press = -g.dot(n);
    const Vector3d kinetic = course::with_friction(FrictionRule::Naive, c, n, v, g, dt) - g;
    EXPECT_NEAR(kinetic.norm(), 0.5 * press, 1e-12);
    EXPECT_NEAR(kinetic.normalized().dot(v.normalized()), -1.0, 1e-12);
    // The capped friction alone, over one explicit step, never turns v back.
    const Vector3d capped = course::with_friction(FrictionRule::LowSpeed, c, n, v, g, dt) - g;
    EXPECT_GE((v + dt * capped).dot(v), -1e-12 * v.squaredNorm());
  }
  // At rest: held exactly while the pull along the plane is at most mu_s N.
  const Vector3d up = Vector3d::UnitY();
  const Vector3d holds(0.6 * 9.81, -9.81, 0.0), slips(0.6 * 9.81 * (1 + 1e-9), -9.81, 0.0);
  EXPECT_EQ(course::with_friction(FrictionRule::Clamp, c, up, Vector3d::Zero(), holds, dt),
            Vector3d(0.0, -9.81, 0.0));
  const Vector3d slipping =
      course::with_friction(FrictionRule::Clamp, c, up, Vector3d::Zero(), slips, dt);
  EXPECT_NEAR(slipping.x(), slips.x() - 0.5 * 9.81, 1e-12);
}

}  // namespace
}  // namespace bb
