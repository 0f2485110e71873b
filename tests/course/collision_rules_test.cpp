// The course's collision rules: the restitution blend's conservation laws and limits, and
// where each floor rule puts a ball that went below.
#include "course/collision_rules.hpp"

#include <gtest/gtest.h>

namespace bb::course {
namespace {

using Eigen::Vector3d;

double kinetic(double m1, const Vector3d& v1, double m2, const Vector3d& v2) {
  return 0.5 * m1 * v1.squaredNorm() + 0.5 * m2 * v2.squaredNorm();
}

TEST(BlendCollision, ConservesMomentumForEveryRestitution) {
  const double m1 = 1.0, m2 = 2.25;  // "Double bounce": mass = r^2, radii 1 and 1.5
  const Vector3d n = Vector3d(1, -0.3, 0.2).normalized();
  for (double e = 0.0; e <= 1.0; e += 0.05) {
    Vector3d v1(3, 1, 0), v2(-1, 0.5, 2);
    const Vector3d before = m1 * v1 + m2 * v2;
    blend_collision(m1, m2, e, n, v1, v2);
    EXPECT_TRUE((m1 * v1 + m2 * v2).isApprox(before, 1e-14)) << e;
    // Newton's law of restitution along the normal: separation = e * approach.
    const double approach = (Vector3d(3, 1, 0) - Vector3d(-1, 0.5, 2)).dot(n);
    EXPECT_NEAR((v1 - v2).dot(n), -e * approach, 1e-12) << e;
  }
}

TEST(BlendCollision, ReducesToThePlasticAndElasticFormulasAtItsEnds) {
  const double m1 = 0.05, m2 = 0.2;  // "Arrow 2": an arrow and an apple
  const Vector3d n = Vector3d::UnitX();
  // e = 0: both move on together at v1 m1 / (m1 + m2) (seed, plastic collisions).
  Vector3d arrow(60, 0, 0), apple(0, 0, 0);
  blend_collision(m1, m2, 0.0, n, arrow, apple);
  EXPECT_NEAR(arrow.x(), 60 * m1 / (m1 + m2), 1e-12);
  EXPECT_NEAR(apple.x(), arrow.x(), 1e-12);
  // e = 1: the elastic formulas, and kinetic energy is kept.
  Vector3d v1(2, 0, 0), v2(-1, 0, 0);
  const double energy = kinetic(m1, v1, m2, v2);
  blend_collision(m1, m2, 1.0, n, v1, v2);
  EXPECT_NEAR(v1.x(), (2 * (m1 - m2) + 2 * -1 * m2) / (m1 + m2), 1e-12);
  EXPECT_NEAR(v2.x(), (2 * 2 * m1 + -1 * (m2 - m1)) / (m1 + m2), 1e-12);
  EXPECT_NEAR(kinetic(m1, v1, m2, v2), energy, 1e-12);
}

TEST(BlendCollision, EqualMassesExchangeVelocitiesWhenElastic) {
  Vector3d v1(2, 0, 0), v2(-0.5, 0, 0);
  blend_collision(1.0, 1.0, 1.0, Vector3d::UnitX(), v1, v2);
  EXPECT_DOUBLE_EQ(v1.x(), -0.5);
  EXPECT_DOUBLE_EQ(v2.x(), 2.0);
}

TEST(GroundRules, EachPutsTheBallWhereTheSeedSays) {
  // A unit ball 0.2 m into a floor at y = 0, falling at 3 m/s.
  const Vector3d n = Vector3d::UnitY();
  const contact::Proximity p = contact::sphere_plane({0, 0.8, 0}, 1.0, Vector3d::Zero(), n);
  ASSERT_NEAR(p.gap, -0.2, 1e-15);
  for (GroundRule rule : {GroundRule::Reflect, GroundRule::Clamp, GroundRule::Mirror}) {
    Vector3d x(0, 0.8, 0), v(1, -3, 0);
    resolve_fixed(rule, p, 1.0, x, v);
    EXPECT_TRUE(v.isApprox(Vector3d(1, 3, 0))) << ground_rule_name(rule);
    const double expected_height = rule == GroundRule::Reflect ? 0.8
                                   : rule == GroundRule::Clamp ? 1.0
                                                               : 1.2;
    EXPECT_NEAR(x.y(), expected_height, 1e-15) << ground_rule_name(rule);
    EXPECT_EQ(ground_rule(ground_rule_name(rule)), rule);
  }
  // The seed tests height, not direction: a ball below and already rising is turned down.
  Vector3d x(0, 0.8, 0), v(0, 2, 0);
  resolve_fixed(GroundRule::Reflect, p, 1.0, x, v);
  EXPECT_LT(v.y(), 0.0);
}

}  // namespace
}  // namespace bb::course
