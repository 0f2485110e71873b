// The reference on a free box spun about its middle axis: Euler's equations keep energy
// and angular momentum to 1e-9 over the whole run, through the flips.
#include <gtest/gtest.h>

#include "metrics/observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "scene/load_case.hpp"
#include "scene/motion.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(RotationReference, AFreeBoxKeepsEnergyAndAngularMomentumThroughItsFlips) {
  const Scene scene = load_case(test::source_path("cases/spinning_box.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const Vec3 principal = principal_inertia(scene.bodies[0]);
  const auto momentum = [&](const BodyState& s) {
    const Eigen::Matrix3d r = s.orientation.toRotationMatrix();
    return Vec3(r * principal.asDiagonal() * r.transpose() * s.angular_velocity);
  };
  const State& first = run.trajectory.states.front();
  const double e0 = total_energy(scene, first);
  const Vec3 l0 = momentum(first[0]);
  for (const State& s : run.trajectory.states) {
    ASSERT_NEAR(total_energy(scene, s), e0, 1e-9 * e0);
    ASSERT_LT((momentum(s[0]) - l0).norm(), 1e-9 * l0.norm());
  }
  // And it does flip: the middle axis turns over several times in 10 s.
  const ObservableValue flips = measure(scene, scene.observes[0], run.trajectory, nullptr);
  ASSERT_TRUE(flips.value) << flips.note;
  std::printf("reference: %g flips\n", *flips.value);
  EXPECT_GE(*flips.value, 2.0);
}

}  // namespace
}  // namespace bb
