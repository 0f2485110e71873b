// A ball hitting a plank: the rigid-body impulse keeps momentum and angular momentum about
// any point for every restitution in [0, 1] and obeys Newton's law at the contact point;
// the seed's shortcut does not, by exactly what it creates.
#include "course/plank_hit.hpp"

#include <gtest/gtest.h>

#include <random>

namespace bb::course {
namespace {

using contact::angular_momentum;
using contact::HitBody;
using contact::impulse_hit;
using contact::kinetic_energy;
using contact::momentum;

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// The seed's plank: 5 m long, 0.2 m thick and deep, at rest at the origin along x.
HitBody plank(double mass) {
  HitBody p;
  p.mass = mass;
  const double l = 5.0, t = 0.2;
  p.inertia = (Vector3d(t * t + t * t, l * l + t * t, l * l + t * t) * mass / 12.0).asDiagonal();
  return p;
}

/// A ball of radius 0.5 m coming down onto the plank at x along -y.
HitBody ball(double mass, double x, double speed) {
  HitBody b;
  b.mass = mass;
  b.inertia = Matrix3d::Identity() * 0.4 * mass * 0.25;
  b.position = {x, 0.6, 0.0};
  b.velocity = {0.0, -speed, 0.0};
  return b;
}

TEST(PlankHit, TheImpulseKeepsMomentumAndAngularMomentumForEveryRestitution) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<> u(-1.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const double e = 0.25 * (k % 5);
    HitBody a = ball(0.5 + 2.0 * std::abs(u(rng)), 2.4 * u(rng), 1.0 + 4.0 * std::abs(u(rng)));
    HitBody b = plank(1.0 + 3.0 * std::abs(u(rng)));
    a.spin = {u(rng), u(rng), u(rng)};
    b.velocity = {u(rng), 0.2 * u(rng), 0.0};
    b.spin = {0.0, 0.0, 0.3 * u(rng)};
    const Vector3d point(a.position.x(), 0.1, 0.0), normal = Vector3d::UnitY();
    const Vector3d origin(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
    const Vector3d p0 = momentum(a, b), l0 = angular_momentum(a, b, origin);
    const double e0 = kinetic_energy(a, b);
    const auto closing = [&] {
      return (a.velocity + a.spin.cross(point - a.position) - b.velocity -
              b.spin.cross(point - b.position))
          .dot(normal);
    };
    const double before = closing();
    ASSERT_LT(before, 0.0);
    impulse_hit(a, b, point, normal, e);
    EXPECT_LT((momentum(a, b) - p0).norm(), 1e-12 * p0.norm() + 1e-12) << k;
    EXPECT_LT((angular_momentum(a, b, origin) - l0).norm(), 1e-11 * (1.0 + l0.norm())) << k;
    // Newton's law at the contact point, and no energy from nowhere.
    EXPECT_NEAR(closing(), -e * before, 1e-12 * std::abs(before)) << k;
    EXPECT_LE(kinetic_energy(a, b), e0 * (1.0 + 1e-12)) << k;
    if (e == 1.0) {
      EXPECT_NEAR(kinetic_energy(a, b), e0, 1e-12 * e0) << k;
    }
  }
}

// Friction at the impact is an impulse at the same point: momentum and angular momentum
// stay, energy does not grow, and the slip is stopped or only slowed, never turned back.
TEST(PlankHit, FrictionAtTheImpactKeepsMomentumAndNeverReversesTheSlip) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<> u(-1.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    HitBody a = ball(0.5 + std::abs(u(rng)), 2.0 * u(rng), 1.0 + 3.0 * std::abs(u(rng)));
    HitBody b = plank(1.0 + std::abs(u(rng)));
    a.velocity.x() = 3.0 * u(rng);
    a.spin = {0.0, 0.0, 2.0 * u(rng)};
    const Vector3d point(a.position.x(), 0.1, 0.0), normal = Vector3d::UnitY();
    const Vector3d origin(u(rng), u(rng), 0.0);
    const auto slip = [&] {
      return (a.velocity + a.spin.cross(point - a.position) - b.velocity -
              b.spin.cross(point - b.position))
          .x();
    };
    const double jn = impulse_hit(a, b, point, normal, 0.5);
    const Vector3d p0 = momentum(a, b), l0 = angular_momentum(a, b, origin);
    const double e0 = kinetic_energy(a, b), s0 = slip();
    contact::friction_hit(a, b, point, normal, jn, 0.3, 0.2);
    EXPECT_LT((momentum(a, b) - p0).norm(), 1e-12) << k;
    EXPECT_LT((angular_momentum(a, b, origin) - l0).norm(), 1e-11) << k;
    EXPECT_LE(kinetic_energy(a, b), e0 * (1.0 + 1e-12)) << k;
    EXPECT_GE(slip() * s0, -1e-12) << k;
  }
}

// The seed's demo: the ball keeps its speed and turns back, and the plank takes the ball's
// momentum as well. Momentum changes by -(m_ball v_n + m_plank V_n) n, and the energy grows
// by what the plank gained, f^2 / (2 m_plank) + (r x f).J^-1 (r x f) / 2.
TEST(PlankHit, TheSeedsShortcutCreatesExactlyWhatItGivesThePlank) {
  for (double x : {0.0, 1.0, 2.4}) {
    HitBody a = ball(1.0, x, 3.0);
    HitBody b = plank(2.0);
    const Vector3d point(x, 0.1, 0.0), normal = Vector3d::UnitY();
    const Vector3d p0 = momentum(a, b);
    const double e0 = kinetic_energy(a, b);
    const double f = a.mass * a.velocity.dot(normal);
    seed_plank_hit(a, b, point, normal);
    // The plank starts at rest (V_n = 0): the change is the ball's momentum turned back.
    const Vector3d created = -f * normal;
    EXPECT_LT((momentum(a, b) - p0 - created).norm(), 1e-12) << x;
    const Vector3d torque = point.cross(f * normal);
    const double made = 0.5 * f * f / b.mass + 0.5 * torque.dot(b.inertia.ldlt().solve(torque));
    EXPECT_NEAR(kinetic_energy(a, b) - e0, made, 1e-12) << x;
    // Off centre, the plank spins with L / J: the seed's omega for J = 1/12 m l^2.
    EXPECT_NEAR(b.spin.z(), x * f / (b.mass * 25.0 / 12.0 + b.mass * 0.04 / 12.0), 1e-12) << x;
  }
}

}  // namespace
}  // namespace bb::course
