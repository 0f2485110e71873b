// The course integrators behave as the theory says: their observed order of convergence,
// and the energy drift each shows in free fall (seed section 1, "Three beachballs 1").
#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "metrics/errors.hpp"
#include "metrics/order.hpp"
#include "model/motion.hpp"
#include "physics/energy.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "support/course_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::course;

struct OrderCase {
  std::string integrator;
  double expected;
};

void PrintTo(const OrderCase& c, std::ostream* os) {
  *os << c.integrator;
}

class ObservedOrder : public ::testing::TestWithParam<OrderCase> {};

// position_max over the dt sweep of drag_fall, against the GSL reference.
TEST_P(ObservedOrder, MatchesTheMethodsOrderOnDragFall) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord reference = run_accuracy(ReferenceBackend(), scene, scene.sample);
  const RunRecord tighter = run_accuracy(ReferenceBackend().self_check(), scene, scene.sample);
  const double self_check = max_position_difference(reference.trajectory, tighter.trajectory);
  const CourseBackend backend = course(GetParam().integrator);
  std::vector<ErrorPoint> points;
  for (double dt : scene.dt) {
    const RunRecord run = run_accuracy(backend, scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    points.push_back({dt, compare(scene, run.trajectory, reference.trajectory).position_max,
                      error_floor(largest_position(reference.trajectory), self_check, run.steps)});
  }
  // Errors shrink at every halving until they reach the reference's floor.
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i - 1].error > points[i - 1].floor) {
      EXPECT_LT(points[i].error, points[i - 1].error) << i;
    }
  const OrderFit fit = fit_order(points);
  ASSERT_TRUE(fit.slope.has_value()) << "fewer than two errors above the error floor";
  EXPECT_NEAR(*fit.slope, GetParam().expected, 0.15);
}

INSTANTIATE_TEST_SUITE_P(Integrators, ObservedOrder,
                         ::testing::Values(OrderCase{"explicit-euler", 1.0},
                                           OrderCase{"semi-implicit-euler", 1.0},
                                           OrderCase{"velocity-verlet", 2.0},
                                           OrderCase{"rk4", 4.0}),
                         [](const auto& info) {
                           std::string n = info.param.integrator;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

/// Energy change after 2 s of free fall without air, at 1/30 s.
double free_fall_energy_drift(const std::string& integrator) {
  const Scene scene = test::scene_from(R"(name = "free_fall"
dims = 2
duration = 2.0
sample = 0.1
dt = [0.0333333333333333333]
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 100.0, 0.0]
velocity = [2.0, 5.0, 0.0]
)");
  const RunRecord run = run_accuracy(course(integrator), scene, scene.dt[0]);
  return total_energy(scene, run.trajectory.states.back()) -
         total_energy(scene, run.trajectory.states.front());
}

// Position first (the middle ball) gains energy; velocity first loses it; Verlet and RK4
// are exact for constant acceleration.
TEST(EnergyDrift, ExplicitGainsSemiImplicitLosesHigherOrderKeeps) {
  const double explicit_drift = free_fall_energy_drift("explicit-euler");
  const double semi_drift = free_fall_energy_drift("semi-implicit-euler");
  const double verlet_drift = free_fall_energy_drift("velocity-verlet");
  const double rk4_drift = free_fall_energy_drift("rk4");
  EXPECT_GT(explicit_drift, 0.0);
  EXPECT_LT(semi_drift, 0.0);
  EXPECT_LT(std::abs(verlet_drift), 1e-3 * std::abs(semi_drift));
  EXPECT_LT(std::abs(rk4_drift), 1e-3 * std::abs(semi_drift));
  // The two Euler orders err by the same amount in opposite directions: m g^2 dt t / 2.
  EXPECT_NEAR(explicit_drift, -semi_drift, 1e-9);
  EXPECT_NEAR(explicit_drift, 0.5 * 9.81 * 9.81 * (1.0 / 30.0) * 2.0, 1e-9);
}

TEST(Rotation, ConstantSpinTurnsTheOrientationExactly) {
  std::string text = test::kMinimalCase;
  text += "angular_velocity = [0.0, 0.0, 1.5707963267948966]\n";  // a quarter turn per second
  const Scene scene = test::scene_from(text);
  const RunRecord run = run_accuracy(course("semi-implicit-euler"), scene, 0.05);
  ASSERT_EQ(run.status, RunStatus::Ok);
  EXPECT_NEAR(angle_about_z(run.trajectory.states.back()[0].orientation), M_PI / 2.0, 1e-12);
}

}  // namespace
}  // namespace bb
