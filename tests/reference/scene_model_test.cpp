// The reference's contact model: bounces at the exact times and heights, momentum kept
// between bodies, the end of a geometric series of bounces, and what it refuses.
#include "reference/scene_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"

namespace bb {
namespace {

const char* kDrop = R"(name = "drop"
dims = 2
duration = 12.0
sample = 0.0333333333333333333
dt = [0.0333333333333333333]
report_dt = 0.0333333333333333333

[ground]
restitution = 0.8

[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
)";

/// Runs `scene` through the hybrid integrator sample by sample; returns the final state.
State simulate(const Scene& scene, SceneModel& model) {
  HybridIntegrator integrator(model, {}, model.initial_state());
  for (int i = 1; i <= scene.sample_count(); ++i) integrator.advance_to(i * scene.sample);
  State out(scene.bodies.size());
  model.read(integrator.state().data(), out);
  return out;
}

TEST(SceneModel, ADroppedBallBouncesAtTheClosedFormsTimesAndHeights) {
  const Scene scene = test::scene_from(kDrop);
  SceneModel model(scene);
  simulate(scene, model);
  // Constants from the scene: g, radius, drop height, restitution.
  const double g = -scene.gravity.y(), r = scene.bodies[0].radius, h = scene.bodies[0].position.y();
  const double e = scene.ground->restitution, v0 = std::sqrt(2.0 * g * (h - r));
  double contact = v0 / g;
  const BodyEvents& events = model.trace().bodies[0];
  ASSERT_GE(events.contact_times.size(), 12u);
  ASSERT_GE(events.apex_heights.size(), 12u);
  for (int n = 0; n < 12; ++n) {
    EXPECT_NEAR(events.contact_times[n], contact, 1e-9) << "contact " << n;
    contact += 2.0 * std::pow(e, n + 1) * v0 / g;
    EXPECT_NEAR(events.apex_heights[n], r + (h - r) * std::pow(e, 2.0 * (n + 1)), 1e-9)
        << "apex " << n + 1;
  }
  // Right after the first contact the ball rises at e times its impact speed, away from
  // the ground along the contact's normal.
  EXPECT_NEAR(events.post_velocity->y(), e * v0, 1e-9);
  ASSERT_TRUE(events.post_normal.has_value());
  EXPECT_NEAR(events.post_normal->y(), 1.0, 1e-12);
}

TEST(SceneModel, EverSmallerBouncesEndWithTheBallRestingOnTheGround) {
  const Scene scene = test::scene_from(kDrop);
  SceneModel model(scene);
  const State end = simulate(scene, model);
  // The bounces of e = 0.8 from 10 m add up to t0 (1 + 2e / (1 - e)) = 12.52 s: by 14 s the
  // ball rests.
  const Scene longer = test::scene_from(std::string(kDrop).replace(
      std::string(kDrop).find("duration = 12.0"), 15, "duration = 14.0"));
  SceneModel rests(longer);
  const State at_rest = simulate(longer, rests);
  EXPECT_NEAR(at_rest[0].position.y(), 0.5, 1e-9);
  EXPECT_EQ(at_rest[0].velocity.y(), 0.0);
  // Finitely many events: the rule ends the series after a few dozen bounces.
  EXPECT_LT(rests.trace().bodies[0].contact_times.size(), 200u);
  EXPECT_GT(end[0].position.y(), 0.5 - 1e-9);
}

TEST(SceneModel, TwoBallsKeepTheirMomentumAndSeparateAtTheRestitution) {
  const Scene scene = test::scene_from(R"(name = "two"
dims = 2
duration = 2.0
sample = 0.1
dt = [0.1]
report_dt = 0.1
gravity = [0.0, 0.0, 0.0]

[[body]]
name = "small"
radius = 1.0
mass = 1.0
position = [-3.0, 0.0, 0.0]
velocity = [2.0, 0.3, 0.0]

[[body]]
name = "big"
radius = 1.5
mass = 2.25
position = [3.0, 0.5, 0.0]
velocity = [-1.0, 0.0, 0.0]

[[contact]]
bodies = ["small", "big"]
restitution = 0.6
)");
  SceneModel model(scene);
  const State end = simulate(scene, model);
  const double m1 = 1.0, m2 = 2.25;
  const Vec3 before = Vec3{2.0, 0.3, 0.0} * m1 + Vec3{-1.0, 0.0, 0.0} * m2;
  const Vec3 after = end[0].velocity * m1 + end[1].velocity * m2;
  EXPECT_NEAR(after.x(), before.x(), 1e-12);
  EXPECT_NEAR(after.y(), before.y(), 1e-12);
  // One contact, seen by both bodies; the reference's own balance says the same.
  EXPECT_EQ(model.trace().bodies[0].contact_times.size(), 1u);
  EXPECT_EQ(model.trace().bodies[1].contact_times.size(), 1u);
  ASSERT_TRUE(model.trace().first_collision);
  EXPECT_NEAR(model.trace().first_collision->momentum_change.norm(), 0.0, 1e-12);
  EXPECT_LT(model.trace().first_collision->kinetic_energy_after,
            model.trace().first_collision->kinetic_energy_before);
}

TEST(SceneModel, AMovingBoxThatTouchesIsBeyondAnExactAnswer) {
  const Scene scene = test::scene_from(std::string(kDrop) +
                                       "\n[[body]]\nname = \"crate\"\nshape = \"box\"\n"
                                       "half_extents = [0.5, 0.5, 0.5]\nmass = 1.0\n"
                                       "position = [5.0, 3.0, 0.0]\n");
  EXPECT_NE(SceneModel::beyond_exact_answer(scene).find("crate"), std::string::npos);
  EXPECT_EQ(SceneModel::beyond_exact_answer(test::scene_from(kDrop)), "");
}

}  // namespace
}  // namespace bb

namespace bb {
namespace {

TEST(SceneModel, AnImpulseChangesVelocityByJOverMAndSpinByTheLeverArm) {
  const Scene scene = test::scene_from(R"(name = "push"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1]
gravity = [0.0, 0.0, 0.0]

[[body]]
name = "left"
radius = 0.5
mass = 2.0
position = [-1.0, 0.0, 0.0]

[[impulse]]
body = "left"
time = 0.0
impulse = [-2.0, 0.0, 0.0]
point = [-1.0, 0.25, 0.0]
)");
  SceneModel model(scene);
  std::vector<double> y = model.initial_state();
  model.apply_impulse(scene.impulses[0], 0.0, y.data());
  State s(1);
  model.read(y.data(), s);
  EXPECT_EQ(s[0].velocity.x(), -2.0 / 2.0);
  // r x J = (0, 0.25, 0) x (-2, 0, 0) = (0, 0, 0.5); I = 2/5 m r^2 = 0.2.
  EXPECT_NEAR(s[0].angular_velocity.z(), 0.5 / 0.2, 1e-12);
}

// The analytic Jacobian msbdf uses agrees with central differences of derivatives() on a
// spinning box and a ball in drag, Magnus and wind, away from zero relative speed, joined
// by a stretched, damped spring.
TEST(SceneModel, TheAnalyticJacobianAgreesWithNumericalDifferences) {
  const Scene scene = test::scene_from(R"(name = "jacobian"
dims = 3
duration = 1.0
sample = 0.1
dt = [0.1]
[air]
density = 1.2
wind = [2.0, 0.5, -1.0]
[[body]]
name = "ball"
radius = 0.3
mass = 0.2
position = [0.0, 3.0, 0.0]
velocity = [4.0, 1.0, 2.0]
angular_velocity = [3.0, -2.0, 5.0]
drag_coefficient = 0.47
magnus = 0.01
[[body]]
name = "crate"
shape = "box"
half_extents = [0.5, 0.25, 0.125]
mass = 2.0
position = [2.0, 3.0, 0.0]
velocity = [-1.0, 0.0, 0.5]
angular_velocity = [1.0, 4.0, -2.0]
[[spring]]
bodies = ["ball", "crate"]
stiffness = 50.0
damping = 0.7
rest_length = 1.5
)");
  SceneModel model(scene);
  std::vector<double> y = model.initial_state();
  // A turned box, so Euler's equations are not trivially zero.
  const double turn[4] = {0.8, 0.2, -0.4, 0.4};
  std::copy(turn, turn + 4, y.begin() + SceneModel::kPerBody + 6);
  const std::size_t n = model.dimension();
  std::vector<double> analytic(n * n), numeric(n * n), dt_a(n), dt_n(n);
  model.jacobian(0.0, y.data(), analytic.data(), dt_a.data());
  model.HybridModel::jacobian(0.0, y.data(), numeric.data(), dt_n.data());
  double largest = 0.0;
  for (double v : numeric) largest = std::max(largest, std::abs(v));
  ASSERT_GT(largest, 1.0);
  for (std::size_t k = 0; k < n * n; ++k)
    EXPECT_NEAR(analytic[k], numeric[k], 1e-6 * largest) << "row " << k / n << " column " << k % n;
}

}  // namespace
}  // namespace bb
