// The spring loop (seed section 7) that the course, the reference and engines applying
// springs by hand all use: Newton's third law, Hooke's law with a damper along the
// spring, the springs' potential in the total energy, and one answer from both layouts.
#include "model/spring_forces.hpp"

#include <gtest/gtest.h>

#include "model/motion.hpp"
#include "physics/energy.hpp"
#include "physics/equations_of_motion.hpp"
#include "physics/state_forces.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(SpringForces, HookeAndDamperAlongTheSpringEqualAndOpposite) {
  const Scene scene = load_case(test::source_path("cases/spring_pair_damped.toml"));
  const SpringNetwork springs = spring_network(scene);
  // Stretched by 0.1 m, the right end moving away at 0.5 m/s: 100 * 0.1 + 2 * 0.5 = 11 N.
  std::vector<Vec3> x = {{-0.55, 0, 0}, {0.55, 0, 0}}, v = {{0, 0, 0}, {0.5, 0, 0}};
  std::vector<Vec3> f(2, Vec3::Zero());
  add_spring_forces(springs, x.data(), v.data(), f.data());
  EXPECT_NEAR(f[0].x(), 11.0, 1e-12);
  EXPECT_EQ((f[0] + f[1]).norm(), 0.0);
  // The engines' layout gives the same forces.
  State state(2);
  for (int i = 0; i < 2; ++i) state[i].position = x[i], state[i].velocity = v[i];
  StateForces by_hand(scene);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(by_hand.at(state).force[i], f[i]);
  // Without the springs, engines that build their own joints add nothing for them.
  StateForces joints(scene, {false});
  EXPECT_TRUE(joints.model().empty());
  for (int i = 0; i < 2; ++i) EXPECT_EQ(joints.at(state).force[i], Vec3::Zero());
}

TEST(SpringForces, TheEquationsOfMotionAndTheEnergyCarryTheSprings) {
  const Scene scene = load_case(test::source_path("cases/cloth.toml"));
  const EquationsOfMotion equations(scene);
  const State start = initial_state(scene);
  std::vector<Vec3> x, v, omega(start.size()), a(start.size());
  const std::vector<Quat> q(start.size(), Quat::Identity());
  for (const BodyState& s : start) x.push_back(s.position), v.push_back(s.velocity);
  equations.accelerations(x, v, omega, q, a);
  StateForces forces(scene);
  const std::vector<Vec3>& by_hand = forces.at(start).force;
  const SpringNetwork springs = spring_network(scene);
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (scene.bodies[i].fixed) {
      EXPECT_EQ(a[i], Vec3::Zero());
      continue;
    }
    EXPECT_LT((a[i] - (scene.gravity + by_hand[i] / scene.bodies[i].mass)).norm(), 1e-12);
  }
  // The cloth starts jittered off its rest lengths: its springs hold some energy.
  double kinetic_and_gravity = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i)
    if (!scene.bodies[i].fixed)
      kinetic_and_gravity -= scene.bodies[i].mass * scene.gravity.dot(start[i].position);
  const double stored = spring_energy(springs, x.data());
  EXPECT_GT(stored, 0.0);
  EXPECT_NEAR(total_energy(scene, start), kinetic_and_gravity + stored, 1e-9);
}

}  // namespace
}  // namespace bb
