// The stability search brackets a known critical step and terminates whatever a backend does.
#include "run/stability.hpp"

#include <gtest/gtest.h>

#include "metrics/stability_theory.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A test-only backend whose state turns NaN on the first step when dt > critical.
class ThresholdBackend : public Backend {
 public:
  explicit ThresholdBackend(double critical) : critical_(critical) {}
  std::string name() const override { return "threshold"; }
  FeatureSet supports() const override { return {Feature::Gravity, Feature::Drag}; }
  std::unique_ptr<Simulation> start(const Scene& scene, double dt) const override {
    struct Sim : Simulation {
      State state;
      bool blow_up = false;
      void step() override {
        if (blow_up) state[0].position.y() = NAN;
      }
      void read(State& out) const override { out = state; }
    };
    auto sim = std::make_unique<Sim>();
    sim->state.resize(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      sim->state[i].position = scene.bodies[i].position;
    sim->blow_up = dt > critical_;
    return sim;
  }

 private:
  double critical_;
};

Scene searched_scene() {
  std::string text = test::kMinimalCase;
  text += "\n[stability]\ndt_min = 1e-4\ndt_max = 0.5\n";
  return test::scene_from(text);
}

TEST(Stability, BracketsAKnownCriticalStepWithinOnePercent) {
  const Scene scene = searched_scene();
  for (double critical : {0.000137, 0.0123, 0.31}) {
    const StabilityResult r = find_stability(ThresholdBackend(critical), scene);
    ASSERT_EQ(r.status, "bracketed") << critical;
    ASSERT_TRUE(r.critical_dt && r.unstable_dt);
    EXPECT_LE(*r.critical_dt, critical);
    EXPECT_GT(*r.unstable_dt, critical);
    EXPECT_LT((*r.unstable_dt - *r.critical_dt) / critical, 0.01) << critical;
    EXPECT_LE(r.trials, 40);
    EXPECT_NE(r.reason.find("NaN"), std::string::npos) << r.reason;
  }
}

TEST(Stability, UnstableEverywhereAndStableEverywhereAreSaid) {
  const Scene scene = searched_scene();
  const StabilityResult never = find_stability(ThresholdBackend(0.0), scene);
  EXPECT_EQ(never.status, "unstable at every dt tried");
  EXPECT_FALSE(never.critical_dt.has_value());
  EXPECT_EQ(*never.unstable_dt, scene.stability.dt_min);
  EXPECT_EQ(never.trials, 2);
  const StabilityResult always = find_stability(ThresholdBackend(1e9), scene);
  EXPECT_EQ(always.status, "stable at every dt tried");
  EXPECT_EQ(*always.critical_dt, scene.stability.dt_max);
}

TEST(Stability, EnergyGainBeyondTheFactorIsUnstable) {
  // Explicit Euler gains energy m g^2 dt t / 2 in free fall: with a factor barely above 1,
  // large steps count as unstable and small ones do not.
  const Scene scene = test::scene_from(R"(name = "gain"
dims = 2
duration = 4.0
sample = 0.1
dt = [0.1]
[stability]
energy_factor = 1.01
dt_min = 0.001
dt_max = 1.0
[course]
integrators = ["explicit-euler"]
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 100.0, 0.0]
)");
  const Registry registry = Registry::load();
  const auto results = find_stability_all(scene, registry, {"course/explicit-euler"}, 1);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].status, "bracketed");
  EXPECT_NE(results[0].reason.find("energy rose"), std::string::npos) << results[0].reason;
}

TEST(StabilityTheory, EulerLimitIsTerminalSpeedOverGravity) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const auto limit = theoretical_limit(scene, "semi-implicit-euler");
  ASSERT_TRUE(limit.has_value());
  // The mouse is the stiffer body: v_t = sqrt(2 m g / (rho Cd pi r^2)).
  const Body& mouse = scene.bodies[scene.body_index("mouse")];
  const double vt = std::sqrt(2 * mouse.mass * 9.81 / (1.2 * 0.47 * M_PI * 0.01));
  EXPECT_NEAR(limit->dt, vt / 9.81, 1e-12);
  EXPECT_NEAR(theoretical_limit(scene, "rk4")->dt / limit->dt, 2.785 / 2.0, 1e-12);
  EXPECT_FALSE(theoretical_limit(load_case(test::source_path("cases/magnus_throw.toml")), "rk4")
                   .has_value());
}

}  // namespace
}  // namespace bb
