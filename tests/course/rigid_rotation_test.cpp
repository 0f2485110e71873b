// The seed's rotation with physics (section 5): L += T dt, omega = J^-1 L in the world
// frame, the orientation turned by omega dt. Checked as properties: the 2D sequence's
// closed sum, a free body's angular momentum kept exactly, and the flip's energy error
// shrinking as dt halves.
#include "course/rigid_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "observe/observables.hpp"
#include "physics/energy.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// In 2D, about z: L_n = n T dt, omega_n = L_n / J, angle_n = sum omega_k dt =
// T dt^2 n (n + 1) / (2 J), the seed's scalar sequence summed.
TEST(RigidRotation, TwoDimensionalSequenceIsTheSeedsSum) {
  const Vector3d principal(0.5, 2.0, 3.0);
  const Vector3d torque(0.0, 0.0, 1.5);
  const double dt = 0.01;
  Vector3d momentum = Vector3d::Zero(), spin;
  Quaterniond q = Quaterniond::Identity();
  const int n = 50;
  for (int k = 0; k < n; ++k) course::rotate_rigid(principal, torque, dt, momentum, q, spin);
  const double angle = 2.0 * std::atan2(q.z(), q.w());
  EXPECT_NEAR(angle, torque.z() * dt * dt * n * (n + 1) / (2.0 * principal.z()), 1e-12);
  EXPECT_NEAR(spin.z(), n * torque.z() * dt / principal.z(), 1e-12);
}

RunRecord course_run(const Scene& scene, double dt) {
  const CourseBackend backend(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  return run_accuracy(backend, scene, dt);
}

Vector3d angular_momentum(const Scene& scene, const BodyState& s) {
  return course::world_inertia(principal_inertia(scene.bodies[0]), s.orientation) *
         s.angular_velocity;
}

// Free of torque, the box keeps its angular momentum through every flip (kinematic
// rotation, which keeps the spin instead, would not: the inertia turns with the box).
TEST(RigidRotation, AFreeBoxKeepsItsAngularMomentum) {
  const Scene scene = load_case(test::source_path("cases/spinning_box.toml"));
  const RunRecord run = course_run(scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const Vector3d start = angular_momentum(scene, run.trajectory.states.front()[0]);
  for (const State& s : run.trajectory.states)
    ASSERT_LT((angular_momentum(scene, s[0]) - start).norm(), 1e-12 * start.norm());
}

// The explicit sequence gains energy (with L fixed it drifts towards the axis of least
// inertia, where the energy is largest): the error shrinks as dt halves, and the flips
// approach the reference's.
TEST(RigidRotation, TheFlipsEnergyErrorShrinksAsDtHalves) {
  const Scene scene = load_case(test::source_path("cases/spinning_box.toml"));
  double previous = INFINITY;
  for (double dt :
       {scene.dt[scene.dt.size() - 3], scene.dt[scene.dt.size() - 2], scene.dt.back()}) {
    const RunRecord run = course_run(scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const double e0 = total_energy(scene, run.trajectory.states.front());
    double worst = 0.0;
    for (const State& s : run.trajectory.states)
      worst = std::max(worst, std::abs(total_energy(scene, s) - e0) / e0);
    std::printf("dt %.6f s: largest energy change %.3g of the start\n", dt, worst);
    EXPECT_LT(worst, 0.6 * previous) << dt;
    previous = worst;
  }
  EXPECT_LT(previous, 0.15);
}

}  // namespace
}  // namespace bb
