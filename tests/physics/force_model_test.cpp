// The force model is the one place forces are summed: its terms add up in a fixed order,
// skip fixed bodies, leave springs to engines that build joints, and a new term (the
// constant [[body]] force and torque) reaches every backend through it: each one, the
// course methods, the reference and every engine plugin found at run time, moves a body
// under a constant force and torque as the closed form says.
#include "physics/force_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/motion.hpp"
#include "physics/force_terms.hpp"
#include "physics/state_forces.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A box pushed and turned in empty space: a 2 x 1 x 0.5 m box of 2 kg, 4 N along x and
/// 2 N along y at its centre, 0.5 N m about z. `more` adds lines to the case.
std::string pushed_box(const std::string& more = "") {
  return R"(name = "pushed"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01, 0.005]
report_dt = 0.01
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "box"
shape = "box"
half_extents = [1.0, 0.5, 0.25]
mass = 2.0
force = [4.0, 2.0, 0.0]
torque = [0.0, 0.0, 0.5]
)" + more;
}

TEST(ForceModel, AConstantForceAndTorqueIsOneTermOfTheRegistry) {
  const Scene scene = test::scene_from(pushed_box());
  const ForceModel model(scene);
  EXPECT_FALSE(model.empty());
  EXPECT_TRUE(model.torques());
  const State start = initial_state(scene);
  StateForces forces(scene);
  const Loads& loads = forces.at(start);
  EXPECT_EQ(loads.force[0], Vec3(4.0, 2.0, 0.0));
  EXPECT_EQ(loads.torque[0], Vec3(0.0, 0.0, 0.5));
  bool listed = false;
  for (const ForceTermEntry& e : force_terms())
    listed = listed || e.name.find("applied") != std::string::npos;
  EXPECT_TRUE(listed);
  EXPECT_TRUE(scene.features().has(Feature::AppliedForce));
}

TEST(ForceModel, TermsAddUpAndAFixedBodyFeelsNothing) {
  // Drag, Magnus and a constant force on one ball; a fixed ball with a spring to it.
  const Scene scene = test::scene_from(R"(name = "sum"
dims = 3
duration = 1.0
sample = 0.1
dt = [0.01, 0.005]
report_dt = 0.01
[air]
density = 1.2
wind = [1.0, 0.0, 0.0]
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
velocity = [3.0, 4.0, 0.0]
angular_velocity = [0.0, 0.0, 10.0]
drag_coefficient = 0.5
magnus = 0.01
force = [0.0, 0.0, 2.0]
[[body]]
name = "anchor"
radius = 0.1
fixed = true
position = [0.0, 3.0, 0.0]
[[spring]]
bodies = ["ball", "anchor"]
stiffness = 10.0
rest_length = 2.0
)");
  const State s = initial_state(scene);
  StateForces all(scene), without_springs(scene, {false});
  const Vec3 u = s[0].velocity - scene.air->wind;
  const double k = 0.5 * 0.5 * std::numbers::pi * 0.25 * 1.2;
  const Vec3 drag = -k * u.norm() * u, magnus = 0.01 * s[0].angular_velocity.cross(u);
  const Vec3 spring = 10.0 * (3.0 - 2.0) * Vec3::UnitY();
  EXPECT_LT((all.at(s).force[0] - (drag + magnus + Vec3(0, 0, 2) + spring)).norm(), 1e-12);
  EXPECT_LT((without_springs.at(s).force[0] - (drag + magnus + Vec3(0, 0, 2))).norm(), 1e-12);
  EXPECT_EQ(all.at(s).force[1], Vec3::Zero());
  EXPECT_FALSE(all.model().torques());
}

TEST(ForceModel, TheJacobianOfEachTermMatchesFiniteDifferences) {
  const Scene scene = test::scene_from(R"(name = "jac"
dims = 3
duration = 1.0
sample = 0.1
dt = [0.01, 0.005]
report_dt = 0.01
[air]
wind = [1.0, 0.5, 0.0]
[[body]]
name = "a"
radius = 0.5
mass = 1.0
velocity = [3.0, 4.0, -1.0]
angular_velocity = [1.0, 2.0, 10.0]
drag_coefficient = 0.5
magnus = 0.01
[[body]]
name = "b"
radius = 0.5
mass = 1.0
position = [1.0, 2.5, 0.5]
[[spring]]
bodies = ["a", "b"]
stiffness = 10.0
damping = 0.7
rest_length = 2.0
)");
  const ForceModel model(scene);
  State s = initial_state(scene);
  const auto forces_at = [&](const State& at) {
    StateForces f(scene);
    return f.at(at).force;
  };
  std::vector<Vec3> x, v, w;
  std::vector<Quat> q;
  for (const BodyState& b : s)
    x.push_back(b.position), v.push_back(b.velocity), w.push_back(b.angular_velocity),
        q.push_back(b.orientation);
  ForceJacobian jacobian;
  model.jacobian({x.data(), v.data(), q.data(), w.data()}, jacobian);
  const double h = 1e-6;
  for (int by = 0; by < 2; ++by)
    for (Wrt wrt : {Wrt::Position, Wrt::Velocity, Wrt::Spin})
      for (int c = 0; c < 3; ++c) {
        State up = s, down = s;
        Vec3& pu = wrt == Wrt::Position   ? up[by].position
                   : wrt == Wrt::Velocity ? up[by].velocity
                                          : up[by].angular_velocity;
        Vec3& pd = wrt == Wrt::Position   ? down[by].position
                   : wrt == Wrt::Velocity ? down[by].velocity
                                          : down[by].angular_velocity;
        pu[c] += h, pd[c] -= h;
        const std::vector<Vec3> fu = forces_at(up), fd = forces_at(down);
        for (int body = 0; body < 2; ++body) {
          Vec3 analytic = Vec3::Zero();
          for (const JacobianBlock& b : jacobian.blocks())
            if (b.body == body && b.by_body == by && b.wrt == wrt) analytic += b.value.col(c);
          const Vec3 numeric = (fu[body] - fd[body]) / (2.0 * h);
          EXPECT_LT((analytic - numeric).norm(), 1e-6)
              << "body " << body << " by body " << by << " wrt " << int(wrt) << " axis " << c;
        }
      }
}

/// The box's state after `steps` steps of `dt` on `backend`.
BodyState pushed_box_after(const Backend& backend, const Scene& scene, double dt, int steps) {
  std::unique_ptr<Simulation> sim = start_case(backend, scene, dt);
  for (int n = 0; n < steps; ++n) sim->step();
  State out(scene.bodies.size());
  sim->read(out);
  return out[0];
}

TEST(ForceModel, EveryBackendMovesAndTurnsABodyUnderAConstantForceAndTorque) {
  const Scene scene = test::scene_from(pushed_box());
  const Body& box = scene.bodies[0];
  const double t = 1.0, inertia_z = principal_inertia(box).z();
  // x = F t^2 / (2 m), angle = T t^2 / (2 I).
  const Vec3 where = box.force * (t * t / (2.0 * box.mass));
  const double angle = box.torque.z() * t * t / (2.0 * inertia_z);
  BackendSet set = backends_for(scene, test::registry());
  std::vector<const Backend*> backends = set.all;
  backends.push_back(&test::registry().reference());
  for (const Backend* backend : backends) {
    SCOPED_TRACE(backend->name());
    ASSERT_TRUE(scene.features().missing_from(backend->supports()).empty());
    const BodyState end = pushed_box_after(*backend, scene, 0.01, 100);
    // The reference to its tolerance; a first-order step within 2 % at dt = 0.01 s.
    const double tolerance = backend->name() == "reference" ? 1e-9 : 0.02;
    EXPECT_LT((end.position - where).norm(), tolerance * where.norm());
    EXPECT_NEAR(angle_about_z(end.orientation), angle, tolerance * angle);
    EXPECT_NEAR(end.angular_velocity.z(), box.torque.z() * t / inertia_z,
                tolerance * box.torque.z() * t / inertia_z);
  }
  // Every engine plugin found that this scene does not leave out by its needs (springs for
  // the /force builds) takes part: the force stage is theirs too.
  for (const Backend* engine : test::registry().engines()) {
    if (!engine->needs().missing_from(scene.features()).empty()) continue;
    EXPECT_NE(std::find(set.all.begin(), set.all.end(), engine), set.all.end()) << engine->name();
  }
}

TEST(ForceModel, ABackendWithoutTheForceStageIsUnsupportedNotSilentlyWrong) {
  // Bullet's soft body takes points on springs and applies no force of the harness's.
  const Scene scene = test::scene_from(R"(name = "points"
dims = 3
duration = 1.0
sample = 0.1
dt = [0.01, 0.005]
report_dt = 0.01
[[body]]
name = "a"
shape = "point"
mass = 1.0
force = [1.0, 0.0, 0.0]
[[body]]
name = "b"
shape = "point"
mass = 1.0
position = [1.0, 0.0, 0.0]
[[spring]]
bodies = ["a", "b"]
stiffness = 10.0
rest_length = 1.0
)");
  const Backend* soft = test::engine("bullet-softbody");
  BB_SKIP_IF_MISSING(test::not_built({"bullet-softbody"}));
  const std::vector<Feature> missing = scene.features().missing_from(soft->supports());
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(feature_name(missing[0]), "applied-force");
}

}  // namespace
}  // namespace bb
