// ODE with springs, both ways its users build them: `ode` softens a distance joint into a
// spring with ERP and CFM from the ODE manual's formula, `ode/force` adds the spring force
// before each step. The joint's numerical damping is measured, not hidden.
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

class OdeSprings : public ::testing::Test {
 protected:
  void SetUp() override { BB_SKIP_IF_MISSING(test::not_built({"ode", "ode/force"})); }
};

// (a) and (b): both oscillate near the closed form's period; the force added by hand is
// the course's semi-implicit Euler (ODE integrates the same way), while the soft joint
// runs slow and drains the energy of an undamped spring.
TEST_F(OdeSprings, TheJointRunsSlowAndLosesEnergyWhereTheForceByHandDoesNot) {
  const Scene scene = load_case(test::source_path("cases/spring_pair.toml"));
  const double exact = closed_form::spring_pair_period(1.0, 1.0, 100.0);
  const auto period = [&](const RunRecord& run) {
    return *measure(scene, scene.observes[0], run.trajectory, nullptr).value;
  };
  const RunRecord joint = run_accuracy(*engine("ode"), scene, scene.report_dt);
  const RunRecord force = run_accuracy(*engine("ode/force"), scene, scene.report_dt);
  const RunRecord course = run_accuracy(
      CourseBackend({"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"}),
      scene, scene.report_dt);
  for (const RunRecord* run : {&joint, &force, &course})
    ASSERT_EQ(run->status, RunStatus::Ok) << run->backend << ": " << run->reason;
  const auto energy = [&](const RunRecord& run) {
    return total_energy(scene, run.trajectory.states.back()) /
           total_energy(scene, run.trajectory.states.front());
  };
  std::printf(
      "period / closed form: ode %.4f, ode/force %.4f; energy at the end / start: "
      "ode %.3g, ode/force %.3g\n",
      period(joint) / exact, period(force) / exact, energy(joint), energy(force));
  // The issue measured 1.018 for the joint: within 3 percent, and slower than the truth.
  EXPECT_GT(period(joint), exact);
  EXPECT_LT(period(joint), 1.03 * exact);
  EXPECT_NEAR(period(force), period(course), 1e-9);
  EXPECT_LT(energy(joint), 1e-3);
  EXPECT_GT(energy(force), 0.5);
}

// (c) The mapping is in the run: ERP = h k / (h k + c), CFM = 1 / (h k + c).
TEST_F(OdeSprings, TheRunNamesTheJointAndItsErpAndCfm) {
  const Scene scene = load_case(test::source_path("cases/spring_pair_damped.toml"));
  const double h = scene.report_dt, k = 100.0, c = 2.0;
  const RunRecord joint = run_accuracy(*engine("ode"), scene, h);
  EXPECT_NEAR(number_setting(joint.engine_settings, "spring_erp_first"), h * k / (h * k + c),
              1e-15);
  EXPECT_NEAR(number_setting(joint.engine_settings, "spring_cfm_first"), 1.0 / (h * k + c), 1e-15);
}

}  // namespace
}  // namespace bb
