// plank_free, the seed's free plank hit by a ball, run whole: the course's `impulse` rule
// and the reference keep momentum, angular momentum about any point and (e = 1) energy
// across the hit; the course's `seed-plank` rule creates exactly what its shortcut gives:
// momentum -f n, angular momentum -f (x_ball x n) about the origin, and the plank's kinetic
// energy f^2 / 2m + (r x f n).J^-1 (r x f n) / 2, f = m_ball v_n.
#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

struct Totals {
  Vec3 momentum = Vec3::Zero();
  Vec3 angular = Vec3::Zero();  ///< about the point `about`
  double energy = 0.0;
};

Totals totals(const Scene& scene, const State& s, const Vec3& about) {
  Totals t;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Body& b = scene.bodies[i];
    t.momentum += b.mass * s[i].velocity;
    t.angular += angular_momentum(b, s[i]) - about.cross(b.mass * s[i].velocity);
    t.energy += kinetic_energy(b, s[i]);
  }
  return t;
}

RunRecord run(const Scene& scene, const Backend& backend) {
  RunRecord r = run_accuracy(backend, scene, scene.report_dt);
  EXPECT_EQ(r.status, RunStatus::Ok) << r.reason;
  return r;
}

CourseBackend course(const std::string& hit) {
  CourseVariant v{"course", "semi-implicit-euler", "mirror", "clamp"};
  v.hit = hit;
  return CourseBackend(v);
}

TEST(PlankFree, TheImpulseAndTheReferenceKeepMomentumAngularMomentumAndEnergy) {
  const Scene scene = load_case(test::source_path("cases/plank_free.toml"));
  ASSERT_TRUE(scene.gravity.isZero());
  ASSERT_EQ(scene.contacts.at(0).restitution, 1.0);
  for (const RunRecord& r : {run(scene, course("impulse")), run(scene, ReferenceBackend())}) {
    const State &first = r.trajectory.states.front(), &last = r.trajectory.states.back();
    // The plank spins after the hit: otherwise nothing was tested.
    ASSERT_GT(std::abs(last[0].angular_velocity.z()), 0.1) << r.backend;
    for (const Vec3& about : {Vec3(0.0, 0.0, 0.0), Vec3(3.0, -2.0, 0.0)}) {
      const Totals a = totals(scene, first, about), b = totals(scene, last, about);
      EXPECT_LT((b.momentum - a.momentum).norm(), 1e-12) << r.backend;
      EXPECT_LT((b.angular - a.angular).norm(), 1e-11) << r.backend;
      EXPECT_NEAR(b.energy, a.energy, 1e-12) << r.backend;
    }
  }
}

TEST(PlankFree, TheSeedsShortcutCreatesExactlyWhatItGivesThePlank) {
  const Scene scene = load_case(test::source_path("cases/plank_free.toml"));
  const RunRecord r = run(scene, course("seed-plank"));
  const State &first = r.trajectory.states.front(), &last = r.trajectory.states.back();
  const Body &plank = scene.bodies[0], &ball = scene.bodies[1];
  const Vec3 n = Vec3::UnitY();  // from the plank towards the ball
  const double f = ball.mass * first[1].velocity.dot(n);
  const Vec3 arm(ball.position.x() - plank.position.x(), 0.0, 0.0);  // along the plank
  const Totals a = totals(scene, first, Vec3::Zero()), b = totals(scene, last, Vec3::Zero());
  EXPECT_LT((b.momentum - a.momentum + f * n).norm(), 1e-12);
  EXPECT_LT((b.angular - a.angular + f * ball.position.cross(n)).norm(), 1e-12);
  const Vec3 torque = arm.cross(f * n);
  const double inertia_z = plank.mass *
                           (4.0 * plank.half_extents.x() * plank.half_extents.x() +
                            4.0 * plank.half_extents.y() * plank.half_extents.y()) /
                           12.0;
  EXPECT_NEAR(b.energy - a.energy,
              0.5 * f * f / plank.mass + 0.5 * torque.squaredNorm() / inertia_z, 1e-12);
  // The ball goes back with its full speed; the plank spins at L / J.
  EXPECT_NEAR(last[1].velocity.norm(), first[1].velocity.norm(), 1e-12);
  EXPECT_NEAR(last[0].angular_velocity.z(), torque.z() / inertia_z, 1e-12);
}

}  // namespace
}  // namespace bb
