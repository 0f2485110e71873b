// Box2D with springs, both ways its users build them: `box2d` gives each spring a distance
// joint with stiffness and damping (a soft constraint, implicit in the spring), and
// `box2d/force` adds the spring force before each step. Box2D is 2D and single precision;
// the joint's numerical damping is measured, not hidden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "observe/observables.hpp"
#include "physics/energy.hpp"
#include "reference/closed_form.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::engine;
using test::number_setting;

class Box2dSprings : public ::testing::Test {
 protected:
  void SetUp() override { BB_SKIP_IF_MISSING(test::not_built({"box2d", "box2d/force"})); }
};

double energy_ratio(const Scene& scene, const RunRecord& run) {
  return total_energy(scene, run.trajectory.states.back()) /
         total_energy(scene, run.trajectory.states.front());
}

// The joint runs slow and drains an undamped spring's energy; the force added by hand is
// the course's semi-implicit Euler (Box2D integrates the same way), up to float rounding.
TEST_F(Box2dSprings, TheJointRunsSlowAndLosesEnergyWhereTheForceByHandDoesNot) {
  const Scene scene = load_case(test::source_path("cases/spring_pair.toml"));
  const double exact = closed_form::spring_pair_period(1.0, 1.0, 100.0);
  const auto period = [&](const RunRecord& run) {
    return *measure(scene, scene.observes[0], run.trajectory, nullptr).value;
  };
  const RunRecord joint = run_accuracy(*engine("box2d"), scene, scene.report_dt);
  const RunRecord force = run_accuracy(*engine("box2d/force"), scene, scene.report_dt);
  const RunRecord course = run_accuracy(
      CourseBackend({"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"}),
      scene, scene.report_dt);
  for (const RunRecord* run : {&joint, &force, &course})
    ASSERT_EQ(run->status, RunStatus::Ok) << run->backend << ": " << run->reason;
  std::printf(
      "period / closed form: box2d %.4f, box2d/force %.4f; energy at the end / start: "
      "box2d %.3g, box2d/force %.3g\n",
      period(joint) / exact, period(force) / exact, energy_ratio(scene, joint),
      energy_ratio(scene, force));
  // The issue measured 1.0165 for the joint: within 3 percent, and slower than the truth.
  EXPECT_GT(period(joint), exact);
  EXPECT_LT(period(joint), 1.03 * exact);
  EXPECT_NEAR(period(force), period(course), 1e-5 * exact);
  EXPECT_LT(energy_ratio(scene, joint), 1e-3);
  EXPECT_GT(energy_ratio(scene, force), 0.5);
}

// The damper is the case's: a damped pair loses more energy through the joint than the
// same pair undamped, so the joint's damping is the case's c on top of its own.
TEST_F(Box2dSprings, TheCasesDampingAddsToTheJoints) {
  const Scene undamped = load_case(test::source_path("cases/spring_pair.toml"));
  const Scene damped = load_case(test::source_path("cases/spring_pair_damped.toml"));
  const double h = undamped.report_dt;
  const auto early_energy = [&](const Scene& scene) {
    const RunRecord run = run_accuracy(*engine("box2d"), scene, h);
    EXPECT_EQ(run.status, RunStatus::Ok) << run.reason;
    const std::size_t one_second = static_cast<std::size_t>(std::lround(1.0 / scene.sample));
    return total_energy(scene, run.trajectory.states.at(one_second)) /
           total_energy(scene, run.trajectory.states.front());
  };
  EXPECT_LT(early_energy(damped), early_energy(undamped));
}

// The mapping is in the run: the joint's stiffness is the case's k, as a float.
TEST_F(Box2dSprings, TheRunNamesTheJointAndItsStiffness) {
  const Scene scene = load_case(test::source_path("cases/spring_pair_damped.toml"));
  const RunRecord joint = run_accuracy(*engine("box2d"), scene, scene.report_dt);
  EXPECT_EQ(number_setting(joint.engine_settings, "spring_stiffness_first"),
            double(float(scene.springs[0].stiffness)));
}

}  // namespace
}  // namespace bb
