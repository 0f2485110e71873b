// The reference on plank_axis: a plank on an axis, hit at its end, spins at the impulse's
// moment about the axis over the parallel-axis inertia 1/12 m (l^2 + t^2) + m a^2, and the
// point of the plank on the axis never leaves it.
#include <gtest/gtest.h>

#include "observe/observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(HingeReference, APlankOnAnAxisSpinsByTheParallelAxisTheoremAndKeepsItsAnchor) {
  const Scene scene = load_case(test::source_path("cases/plank_axis.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  for (const Hinge& h : scene.hinges) {
    const Body& b = scene.bodies[h.body];
    const double l = 2.0 * b.half_extents.x(), t = 2.0 * b.half_extents.y();
    const double a = (h.anchor - b.position).norm();
    const Impulse& hit = scene.impulses[h.body];
    const double moment = (*hit.point - h.anchor).cross(hit.impulse).z();
    const double expected = moment / (b.mass * (l * l + t * t) / 12.0 + b.mass * a * a);
    const Observe spin{"post_angular_velocity", h.body, 0, 0, ""};
    const ObservableValue measured = measure(scene, spin, run.trajectory, nullptr);
    ASSERT_TRUE(measured.value) << measured.note;
    EXPECT_NEAR(*measured.value, expected, 1e-9) << b.name;
    // The body point on the axis, carried by the body, stays on the anchor.
    const Vec3 local = b.orientation.conjugate() * (h.anchor - b.position);
    for (const State& s : run.trajectory.states)
      ASSERT_LT((s[h.body].position + s[h.body].orientation * local - h.anchor).norm(), 1e-9)
          << b.name;
  }
}

// falling_wall: a wall on its lee bottom edge, tipped by the wind on its face. Until it
// lands, J w^2 / 2 + m g y_c - (h/2) F sin(phi) stays what it was (the wind's work is its
// torque (h/2) F cos(phi) over the turn); early on, phi follows the small-angle closed form
// phi = (tau0 / k)(cosh(sqrt(k / J) t) - 1), tau0 = h/2 F - m g t/2, k = m g h/2; the wall
// whose wind is too weak never moves; the strong one ends flat on the ground.
TEST(HingeReference, TheFallingWallKeepsItsEnergyBalanceAndFollowsTheSmallAngleForm) {
  const Scene scene = load_case(test::source_path("cases/falling_wall.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const int strong = scene.body_index("strong"), weak = scene.body_index("weak");
  const Body& b = scene.bodies[strong];
  const double m = b.mass, g = -scene.gravity.y(), h = 2.0 * b.half_extents.y(),
               t = 2.0 * b.half_extents.x(), f = b.wind_force.x();
  const double j = m * (h * h + t * t) / 3.0, k = m * g * h / 2.0,
               tau0 = h / 2.0 * f - m * g * t / 2.0;
  ASSERT_GT(tau0, 0.0);
  const auto& states = run.trajectory.states;
  const auto& times = run.trajectory.times;
  double energy0 = 0.0;
  bool checked_small = false;
  for (std::size_t n = 0; n < states.size(); ++n) {
    const BodyState& s = states[n][strong];
    // The tilt towards the wind's side: the wall turns clockwise about z.
    const double phi = -2.0 * std::atan2(s.orientation.z(), s.orientation.w());
    if (phi > 1.5) break;  // near the ground: landing next
    const double w = s.angular_velocity.z();
    const double energy = 0.5 * j * w * w + m * g * s.position.y() - h / 2.0 * f * std::sin(phi);
    if (n == 0) energy0 = energy;
    EXPECT_NEAR(energy, energy0, 1e-9 * std::abs(energy0)) << times[n];
    if (!checked_small && phi > 0.02) {
      const double closed = tau0 / k * (std::cosh(std::sqrt(k / j) * times[n]) - 1.0);
      EXPECT_NEAR(phi, closed, 0.02 * closed) << times[n];
      checked_small = true;
    }
    EXPECT_EQ(states[n][weak].position, scene.bodies[weak].position) << times[n];
  }
  EXPECT_TRUE(checked_small);
  const BodyState& end = states.back()[strong];
  EXPECT_NEAR(end.position.y(), b.half_extents.x(), 1e-9);
  EXPECT_EQ(end.angular_velocity.norm(), 0.0);
}

}  // namespace
}  // namespace bb
