// A force term added the documented way (a ForceTerm with its force, derivatives, potential
// energy and supply, registered once) is judged exactly as its twin built from the case's own
// parts: an anchor spring F = -k (x - p) - c v beside a fixed pivot at p and a [[spring]] of
// rest length 0. Energy, the divergence bound, the stability verdicts and the theory all
// come from the force model, so none of them may tell the two apart.
#include <gtest/gtest.h>

#include <cmath>

#include "course/stability_theory.hpp"
#include "physics/energy.hpp"
#include "physics/force_terms.hpp"
#include "run/accuracy_run.hpp"
#include "run/divergence.hpp"
#include "run/stability.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

constexpr double kStiffness = 40.0;  // N/m
constexpr double kDamping = 0.0;     // N s/m

/// F = -k (x - p) - c v on the body named "bob", p the origin.
class AnchorSpringTerm : public ForceTerm {
 public:
  explicit AnchorSpringTerm(int bob) : bob_(bob) {}
  void add(const BodyStates& s, Vec3* force, Vec3*) const override {
    force[bob_] += -kStiffness * s.position[bob_] - kDamping * s.velocity[bob_];
  }
  void add_jacobian(const BodyStates&, ForceJacobian& out) const override {
    out.add(bob_, bob_, Wrt::Position, -kStiffness * Eigen::Matrix3d::Identity());
    out.add(bob_, bob_, Wrt::Velocity, -kDamping * Eigen::Matrix3d::Identity());
  }
  bool stores_energy() const override { return true; }
  double potential_energy(const BodyStates& s) const override {
    return 0.5 * kStiffness * s.position[bob_].squaredNorm();
  }
  double supply(const BodyStates& start, double) const override { return potential_energy(start); }

 private:
  int bob_;
};

std::unique_ptr<ForceTerm> make_anchor_spring(const World& scene, const ForceOptions&) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].name == "bob" && scene.springs.empty())
      return std::make_unique<AnchorSpringTerm>(static_cast<int>(i));
  return nullptr;
}

/// A 1 kg bob 1.5 m from the anchor, thrown across: a large swing in the plane.
const char* kCommon = R"(dims = 2
duration = 4.0
sample = 0.05
dt = [0.05, 0.025]
report_dt = 0.025
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "bob"
shape = "point"
mass = 1.0
position = [1.5, 0.0, 0.0]
velocity = [0.0, 6.0, 0.0]
[course]
integrators = ["explicit-euler", "semi-implicit-euler"]
)";

Scene with_term() {
  return test::scene_from("name = \"term\"\n" + std::string(kCommon));
}

Scene twin() {
  return test::scene_from("name = \"twin\"\n" + std::string(kCommon) + R"(
[[body]]
name = "pivot"
shape = "point"
mass = 1.0
fixed = true
position = [0.0, 0.0, 0.0]
[[spring]]
bodies = ["bob", "pivot"]
stiffness = 40.0
damping = 0.0
rest_length = 0.0
)");
}

/// The backend called `name` among `set`'s (which owns the course variants).
const Backend& named(const BackendSet& set, const std::string& name) {
  for (const Backend* b : set.all)
    if (b->name() == name) return *b;
  throw std::runtime_error("no backend " + name);
}

TEST(AddedForceTerm, IsJudgedExactlyAsItsSpringTwin) {
  const ForceTermRegistration anchor({"anchor spring (a test's own term)", make_anchor_spring});
  const Scene term = with_term(), spring = twin();
  const BackendSet term_backends = backends_for(term, test::registry());
  const BackendSet twin_backends = backends_for(spring, test::registry());

  // Energy: the same total at every sample of the same motion.
  const RunRecord run =
      run_accuracy(named(term_backends, "course/semi-implicit-euler"), term, 0.025);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  EnergyMeter term_energy(term), twin_energy(spring);
  for (const State& s : run.trajectory.states) {
    State with_pivot = s;
    with_pivot.push_back({Vec3::Zero(), Vec3::Zero(), Quat::Identity(), Vec3::Zero()});
    EXPECT_NEAR(term_energy(s), twin_energy(with_pivot), 1e-12 * twin_energy(with_pivot));
  }
  // Its kinetic energy swings over most of the total: a meter that left out the term's
  // potential energy would see the energy change by that much.
  EXPECT_GT(term_energy(run.trajectory.states.front()), 40.0);

  // The divergence bound: the same scale, the spring's stored energy and the throw.
  const DivergenceBounds a = divergence_bounds(term), b = divergence_bounds(spring);
  EXPECT_NEAR(a.scale.total(), b.scale.total(), 1e-12 * b.scale.total());
  EXPECT_NEAR(a.scale.forces, 0.5 * kStiffness * 1.5 * 1.5, 1e-12);

  // The theory: the same stiffest mode, omega = sqrt(k / m).
  for (const char* integrator : {"explicit-euler", "semi-implicit-euler"}) {
    SCOPED_TRACE(integrator);
    const auto ta = theoretical_limit(term, integrator), tb = theoretical_limit(spring, integrator);
    ASSERT_TRUE(ta && tb);
    EXPECT_NEAR(ta->dt, tb->dt, 1e-12);
  }
  EXPECT_NEAR(theoretical_limit(term, "semi-implicit-euler")->dt, 2.0 / std::sqrt(kStiffness),
              1e-6);
  EXPECT_EQ(theoretical_limit(term, "explicit-euler")->dt, 0.0);

  // The stability verdicts, backend by backend: the same status and the same largest step.
  for (const char* name : {"course/explicit-euler", "course/semi-implicit-euler"}) {
    SCOPED_TRACE(name);
    const StabilityResult sa = find_stability(named(term_backends, name), term);
    const StabilityResult sb = find_stability(named(twin_backends, name), spring);
    EXPECT_EQ(sa.status, sb.status) << sa.reason << " / " << sb.reason;
    EXPECT_EQ(sa.critical_dt.has_value(), sb.critical_dt.has_value());
    if (sa.critical_dt && sb.critical_dt) {
      EXPECT_DOUBLE_EQ(*sa.critical_dt, *sb.critical_dt);
    }
  }
  EXPECT_EQ(find_stability(named(term_backends, "course/explicit-euler"), term).status,
            "unstable at every dt tried");

  // No backend calls the swing a divergence.
  std::vector<const Backend*> backends = term_backends.all;
  backends.push_back(&test::registry().reference());
  for (const Backend* backend : backends) {
    if (backend->name() == "course/explicit-euler") continue;  // it does blow up
    SCOPED_TRACE(backend->name());
    const RunRecord r =
        run_accuracy(*backend, term, backend->name() == "reference" ? term.sample : 0.025);
    EXPECT_NE(r.status, RunStatus::Diverged) << r.reason;
  }
}

}  // namespace
}  // namespace bb
