// The stability search brackets a known critical step and terminates whatever a backend does.
#include "run/stability.hpp"

#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "metrics/spring_modes.hpp"
#include "metrics/stability_theory.hpp"
#include "scene/case_error.hpp"
#include "scene/load_case.hpp"
#include "support/course_support.hpp"
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

/// A test-only backend that counts the steps its runs take.
class CountingBackend : public Backend {
 public:
  std::string name() const override { return "counting"; }
  FeatureSet supports() const override { return {Feature::Gravity, Feature::Drag}; }
  std::unique_ptr<Simulation> start(const Scene& scene, double) const override {
    struct Sim : Simulation {
      State state;
      long* steps;
      void step() override { ++*steps; }
      void read(State& out) const override { out = state; }
    };
    auto sim = std::make_unique<Sim>();
    sim->state.resize(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      sim->state[i].position = scene.bodies[i].position;
    sim->steps = &steps_;
    return sim;
  }
  mutable long steps_ = 0;
};

// A trial keeps to the cap of steps every run keeps to (kMaxStepsPerRun): past it, it takes
// no step and says why, and a search whose range passes it is refused before any trial.
TEST(Stability, NoTrialPassesTheStepCapOfARun) {
  Scene scene = searched_scene();
  const CountingBackend counting;
  const StabilityTrial within = try_step(counting, scene, 0.05);
  EXPECT_TRUE(within.stable);
  EXPECT_EQ(counting.steps_, 20);
  counting.steps_ = 0;
  const StabilityTrial past = try_step(counting, scene, 1e-9);
  EXPECT_FALSE(past.stable);
  EXPECT_NE(past.reason.find("not run"), std::string::npos) << past.reason;
  EXPECT_EQ(counting.steps_, 0);
  scene.stability.dt_min = 1e-9;
  EXPECT_THROW(find_stability(counting, scene), CaseError);
  EXPECT_EQ(counting.steps_, 0);
}

// The search's range is checked at load: a dt_min the case gives that passes the cap is
// refused at its line (tests/bad_cases/stability_dt_min_of_billions_of_steps.toml); a
// default one (a quarter of the finest dt) is raised to the cap.
TEST(Stability, ADefaultSearchRangeIsRaisedToTheStepCap) {
  const Scene scene = test::scene_from(R"(name = "long"
dims = 2
duration = 100.0
sample = 0.001
dt = [0.001, 0.00002]
report_dt = 0.001
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
)");
  EXPECT_NEAR(scene.stability.dt_min, 100.0 / kMaxStepsPerRun, 1e-18);
  EXPECT_GT(scene.stability.dt_max, scene.stability.dt_min);
}

using test::course;

// Stable means bounded (DESIGN.md): semi-implicit Euler 1 percent below 2 / omega swings
// its energy far from its start and is stable; 1 percent above it, and explicit Euler on
// the undamped spring at any step, the energy grows without bound.
TEST(Stability, ABoundedSwingIsStableAndGrowthIsNot) {
  const Scene scene = load_case(test::source_path("cases/spring_pair.toml"));
  const double limit = 2.0 / std::sqrt(100.0 / 0.5);  // omega^2 = k / mu, mu = 0.5 kg
  const StabilityTrial below = try_step(course("semi-implicit-euler"), scene, 0.99 * limit);
  EXPECT_TRUE(below.stable) << below.reason;
  const StabilityTrial above = try_step(course("semi-implicit-euler"), scene, 1.01 * limit);
  EXPECT_FALSE(above.stable);
  const StabilityTrial euler = try_step(course("explicit-euler"), scene, 1e-3);
  EXPECT_FALSE(euler.stable);
  EXPECT_NE(euler.reason.find("grows without bound"), std::string::npos) << euler.reason;
}

TEST(Stability, SpringPairBracketsSemiImplicitEulerWithinOnePercentOfTwoOverOmega) {
  const Scene scene = load_case(test::source_path("cases/spring_pair.toml"));
  const auto results = find_stability_all(
      scene, Registry::load(), {"course/semi-implicit-euler", "course/explicit-euler"}, 2);
  ASSERT_EQ(results.size(), 2u);
  const double two_over_omega = 2.0 / std::sqrt(100.0 / 0.5);
  for (const StabilityResult& r : results) {
    ASSERT_TRUE(r.theory.has_value()) << r.backend;
    if (r.backend == "course/explicit-euler") {
      EXPECT_EQ(r.status, "unstable at every dt tried");
      EXPECT_EQ(*r.theory, 0.0) << "theory: unstable at every dt";
    } else {
      EXPECT_EQ(r.status, "bracketed");
      EXPECT_NEAR(*r.theory, two_over_omega, 1e-9 * two_over_omega);
      EXPECT_NEAR(*r.critical_dt / two_over_omega, 1.0, 0.01);
    }
  }
}

TEST(StabilityTheory, LinearLimitsOfTheIntegratorsOnAnOscillator) {
  const double omega = 10.0;
  EXPECT_NEAR(linear_stability_limit("semi-implicit-euler", omega, 0.0), 0.2, 1e-8);
  EXPECT_NEAR(linear_stability_limit("velocity-verlet", omega, 0.0), 0.2, 1e-8);
  EXPECT_NEAR(linear_stability_limit("rk4", omega, 0.0), 2.0 * std::sqrt(2.0) / omega, 1e-8);
  EXPECT_EQ(linear_stability_limit("explicit-euler", omega, 0.0), 0.0);
  // Damped: explicit Euler holds while det = 1 - gamma h + omega^2 h^2 <= 1: h <= gamma /
  // omega^2; semi-implicit Euler while omega^2 h^2 + 2 gamma h <= 4.
  EXPECT_NEAR(linear_stability_limit("explicit-euler", omega, 5.0), 0.05, 1e-8);
  const double gamma = 5.0;
  EXPECT_NEAR(linear_stability_limit("semi-implicit-euler", omega, gamma),
              (-gamma + std::sqrt(gamma * gamma + 4.0 * omega * omega)) / (omega * omega), 1e-8);
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
