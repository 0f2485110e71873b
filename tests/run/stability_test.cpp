// The stability search brackets a known critical step, probes below it, reports bands where
// stability is not monotone in dt, and terminates whatever a backend does.
#include "run/stability.hpp"

#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "course/spring_modes.hpp"
#include "course/stability_theory.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "run/registry.hpp"
#include "run/stability_watch.hpp"
#include "study/case_error.hpp"
#include "support/course_support.hpp"
#include "support/slow_backend.hpp"
#include "support/test_support.hpp"
#include "support/verdict_backends.hpp"

namespace bb {
namespace {

using test::BandBackend;
using test::ThresholdBackend;

Scene searched_scene() {
  std::string text = test::kMinimalCase;
  text += "\n[stability]\ndt_min = 1e-4\ndt_max = 0.5\n";
  return test::scene_from(text);
}

// A trial times its step loop, for the report's floor: at least what its steps take.
TEST(StabilityTrialTime, ATrialTimesItsStepLoop) {
  const Scene scene = test::scene_from(test::kMinimalCase);
  const StabilityTrial trial = try_step(test::SlowBackend(1e-4), scene, 0.05, 20);
  EXPECT_TRUE(trial.stable) << trial.reason;
  EXPECT_GE(trial.step_seconds, 20 * 1e-4);
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

// The bisection's first step (the geometric mean of 1e-4 and 0.5, 0.0071 s) lands in the
// upper stable band and narrows down to its top; the probes below it find the unstable band
// and the search narrows down both its edges.
TEST(Stability, StabilityThatIsNotMonotoneIsReportedAsBands) {
  const Scene scene = searched_scene();
  const StabilityResult r = find_stability(BandBackend(0.003, 0.006, 0.01), scene);
  EXPECT_EQ(r.status, "not monotone");
  ASSERT_TRUE(r.critical_dt && r.unstable_dt);
  EXPECT_LE(*r.critical_dt, 0.003);
  EXPECT_GT(*r.critical_dt, 0.003 / 1.001);
  EXPECT_GT(*r.unstable_dt, 0.003);
  ASSERT_EQ(r.bands.size(), 4u);
  const bool stable[] = {true, false, true, false};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(r.bands[i].stable, stable[i]) << i;
  EXPECT_EQ(r.bands[0].from, scene.stability.dt_min);
  EXPECT_NEAR(r.bands[1].to / 0.006, 1.0, 0.01);
  EXPECT_NEAR(r.bands[2].from / 0.006, 1.0, 0.01);
  EXPECT_NEAR(r.bands[2].to / 0.01, 1.0, 0.001);
  EXPECT_EQ(r.bands[3].to, scene.stability.dt_max);
  EXPECT_NE(r.bands[1].reason.find("NaN"), std::string::npos) << r.bands[1].reason;
  EXPECT_LE(r.trials, StabilitySearch::kMaxTrials);
}

// Counting work, not time: the probes add at most four trials to a search whose threshold
// is single (two ends and 14 halvings of [1e-4, 0.5] to 0.1 percent).
TEST(Stability, TheProbesCostAtMostFourTrials) {
  const Scene scene = searched_scene();
  for (double critical : {0.000137, 0.0123, 0.31}) {
    const StabilityResult r = find_stability(ThresholdBackend(critical), scene);
    EXPECT_EQ(r.status, "bracketed");
    EXPECT_LE(r.trials, 16 + 4) << critical;
    EXPECT_EQ(r.bands.size(), 2u);
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
  std::unique_ptr<Simulation> start_run(const World& scene, const BackendSettings&,
                                        double) const override {
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
  // The case's 1 s at 0.05 s is 20 steps; a trial takes at least kMinTrialSteps.
  EXPECT_EQ(counting.steps_, std::max(20L, kMinTrialSteps));
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

// Stable means bounded (docs/design.md): semi-implicit Euler 1 percent below 2 / omega swings
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

// spring_pair_damped: explicit Euler's limit is gamma / omega^2 = 0.02 s. Above it the
// oscillation compounds until the spring folds through itself, which caps the energy far
// above anything the scene holds: a runaway, not a bound. (The search used to find 0.0325.)
TEST(Stability, ExplicitEulerOnTheDampedSpringStopsAtTheTheory) {
  const Scene scene = load_case(test::source_path("cases/spring_pair_damped.toml"));
  const StabilityResult r = find_stability(course("explicit-euler"), scene);
  const auto theory = theoretical_limit(scene, "explicit-euler");
  ASSERT_TRUE(theory && r.critical_dt) << r.status;
  EXPECT_NEAR(theory->dt, 0.02, 1e-3);
  // Just above the limit the growth is too slow to show within the case's 10 s.
  EXPECT_GE(*r.critical_dt, 0.99 * theory->dt);
  EXPECT_LE(*r.critical_dt, 1.05 * theory->dt);
  EXPECT_EQ(r.status, "bracketed");
  const StabilityTrial folded = try_step(course("explicit-euler"), scene, 0.03);
  EXPECT_FALSE(folded.stable);
  EXPECT_EQ(folded.growth, "runaway") << folded.reason;
}

// Drift that adds is not instability: explicit Euler's energy error on a parabola grows
// linearly (m g^2 T dt / 2), at every step.
TEST(Stability, SteadyDriftIsStableAndSaysSo) {
  const Scene scene = load_case(test::source_path("cases/arrow.toml"));
  for (double dt : {0.0423, 0.09}) {
    const StabilityTrial t = try_step(course("explicit-euler"), scene, dt);
    EXPECT_TRUE(t.stable) << dt << ": " << t.reason;
    EXPECT_EQ(t.growth, "drift") << dt;
    EXPECT_NE(t.reason.find("drift that adds"), std::string::npos) << t.reason;
  }
}

// spinning_box: semi-implicit Euler's energy error grows with the tennis-racket wobble and
// stops at |L|^2 / (2 I_min) once the spin has moved to the axis of least inertia: bounded.
TEST(Stability, AnEnergyBoundedByTheAngularMomentumIsStable) {
  const Scene scene = load_case(test::source_path("cases/spinning_box.toml"));
  for (double dt : {0.004, scene.report_dt, 0.05}) {
    const StabilityTrial t = try_step(course("semi-implicit-euler"), scene, dt);
    EXPECT_TRUE(t.stable) << dt << ": " << t.reason;
  }
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

// sproing_2d's stability search begins at its finest dt, one of its accuracy runs: that run
// judges the trial on its own steps, the same verdict the search's own trial gives (stable
// and unstable), and a search handed it uses it instead of running the trial again (a
// verdict it could not have found itself shows it was taken).
TEST(Stability, AnAccuracyRunAtTheSearchsFirstStepJudgesItsTrial) {
  const Scene scene = load_case(test::source_path("cases/sproing_2d.toml"));
  const double dt = scene.stability.dt_min;
  ASSERT_EQ(dt, scene.dt.back());
  for (const char* integrator : {"semi-implicit-euler", "explicit-euler"}) {
    SCOPED_TRACE(integrator);
    const RunRecord run = run_accuracy(course(integrator), scene, dt, true);
    ASSERT_TRUE(run.stability_trial);
    const StabilityTrial own = try_step(course(integrator), scene, dt);
    EXPECT_EQ(run.stability_trial->stable, own.stable);
    EXPECT_EQ(run.stability_trial->reason, own.reason);
    EXPECT_EQ(run.stability_trial->growth, own.growth);
    EXPECT_FALSE(run_accuracy(course(integrator), scene, scene.dt.front(), true).stability_trial)
        << "no trial where the search does not begin";
    EXPECT_FALSE(run_accuracy(course(integrator), scene, dt).stability_trial)
        << "none unless asked";
  }
  const Registry registry = Registry::load();
  const std::string name = "course/semi-implicit-euler";
  KnownTrials known;
  known[{name, scene.stability.dt_max}] = {false, "handed in", "diverged"};
  known[{name, dt}] = {false, "handed in", "diverged"};
  const std::vector<StabilityResult> found =
      find_stability_all(scene, registry, {name}, 1, nullptr, false, 0.0, known);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].status, "unstable at every dt tried");
  EXPECT_EQ(found[0].reason, "handed in");
  EXPECT_EQ(found[0].trials, 2);
}

}  // namespace
}  // namespace bb
