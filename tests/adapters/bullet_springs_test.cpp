// Springs in Bullet three ways: btGeneric6DofSpring2Constraint (bullet, bullet-float), forces
// applied by hand before each step (bullet/force) and one btSoftBody (bullet-softbody).
// Each test skips the backends whose plugins were not built.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "seam/engine_catalogue.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::engine;
using test::number_setting;
using test::registry;
using test::setting;
using test::text_setting;

/// The case's observable of `kind` (period/left, max_stretch) measured on `run`.
std::optional<double> observable(const Scene& scene, const RunRecord& run,
                                 const std::string& kind) {
  for (const Observe& o : scene.observes)
    if (o.kind == kind) {
      return measure(scene, o, run.trajectory, nullptr).value;
    }
  return std::nullopt;
}

/// Largest distance between two runs' positions over their common samples.
double largest_gap(const RunRecord& a, const RunRecord& b) {
  double gap = 0.0;
  const std::size_t n = std::min(a.trajectory.states.size(), b.trajectory.states.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < a.trajectory.states[k].size(); ++i)
      gap = std::max(
          gap, (a.trajectory.states[k][i].position - b.trajectory.states[k][i].position).norm());
  return gap;
}

/// The closed-form period of the two-mass spring cases: 2 pi sqrt(mu / k), mu = 1/2 kg.
double two_mass_period(double k) {
  return 2.0 * M_PI * std::sqrt(0.5 / k);
}

/// The period semi-implicit Euler gives the oscillator w at step dt: 2 pi dt / theta with
/// cos theta = 1 - (w dt)^2 / 2 (stable for w dt < 2).
double semi_implicit_euler_period(double w, double dt) {
  return 2.0 * M_PI * dt / std::acos(1.0 - 0.5 * w * w * dt * dt);
}

// (a) At k = 100 N/m and 1/60 s (w dt = 0.24, below the limit of 0.25) the constraint's
// spring is the case's: both ways swing with the closed-form period, semi-implicit Euler's
// 0.1% short of it, and the hand force is the course's semi-implicit Euler to rounding.
TEST(BulletSprings, SpringPairOscillatesWithTheClosedFormPeriod) {
  const Scene scene = test::bundled_case("spring_pair");
  const double exact = two_mass_period(100.0);
  for (const char* name : {"bullet", "bullet-float", "bullet/force"}) {
    const Backend* b = engine(name);
    if (b == nullptr) continue;
    const RunRecord run = run_accuracy(*b, scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << name << ": " << run.reason;
    const std::optional<double> period = observable(scene, run, "period");
    ASSERT_TRUE(period) << name;
    std::printf("%s at 1/60 s: period %.5f s, %.4f of 2 pi sqrt(mu/k) = %.5f s\n", name, *period,
                *period / exact, exact);
    // Band: semi-implicit Euler's 0.1% plus the crossing times' step-sized scatter.
    EXPECT_NEAR(*period / exact, 1.0, 0.01) << name;
  }
  const Backend* force = engine("bullet/force");
  BB_SKIP_IF_MISSING(test::not_built({"bullet/force"}));
  const RunRecord by_hand = run_accuracy(*force, scene, scene.report_dt);
  const BackendSet set = backends_for(scene, registry());
  for (const Backend* b : set.all)
    if (b->name() == "course/semi-implicit-euler") {
      const RunRecord course = run_accuracy(*b, scene, scene.report_dt);
      const double gap = largest_gap(by_hand, course);
      std::printf("bullet/force - course/semi-implicit-euler: %.3g m over 10 s\n", gap);
      // The same update, v += F/m dt then x += v dt; only the rounding differs.
      EXPECT_LT(gap, 1e-9);
    }
  // Below the limit the joint applies the same impulse as the hand force.
  if (const Backend* joint = engine("bullet")) {
    const double gap = largest_gap(run_accuracy(*joint, scene, scene.report_dt), by_hand);
    std::printf("bullet - bullet/force: %.3g m over 10 s\n", gap);
    EXPECT_LT(gap, 1e-6);
  }
}

// (b) At k = 1e5 N/m and 1/240 s (w dt = 1.86) limitIfNeeded swaps k for m / (16 dt^2) =
// 1800 N/m, so the constraint swings sqrt(1e5 / 1800) = 7.45 times slower than the case;
// the hand force keeps k and semi-implicit Euler's period at w dt = 1.86, 0.777 of exact.
TEST(BulletSprings, TheStiffSpringIsLimitedInTheJointNotByHand) {
  const Scene scene = test::bundled_case("spring_pair_stiff");
  const double dt = scene.report_dt, exact = two_mass_period(1e5);
  const double limited_k = 0.5 / (16.0 * dt * dt);
  for (const char* name : {"bullet", "bullet-float"}) {
    const Backend* b = engine(name);
    if (b == nullptr) continue;
    const RunRecord run = run_accuracy(*b, scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << name << ": " << run.reason;
    const std::optional<double> period = observable(scene, run, "period");
    ASSERT_TRUE(period) << name;
    const double ratio = *period / exact;
    std::printf("%s at 1/240 s, k = 1e5: period %.5f s, %.3f times 2 pi sqrt(mu/k)\n", name,
                *period, ratio);
    // Far above 1: at least 5 (the rule gives 7.45; semi-implicit Euler on 1800 N/m at
    // w dt = 0.25 is within 0.3% of its own closed form).
    EXPECT_GT(ratio, 5.0) << name;
    EXPECT_NEAR(ratio, std::sqrt(1e5 / limited_k), 0.05 * std::sqrt(1e5 / limited_k)) << name;
    EXPECT_NEAR(number_setting(run.engine_settings, "spring_stiffness_used_max"), limited_k,
                1e-9 * limited_k);
    EXPECT_EQ(number_setting(run.engine_settings, "springs_stiffness_limited"), 1.0);
  }
  if (const Backend* force = engine("bullet/force")) {
    const RunRecord run = run_accuracy(*force, scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const std::optional<double> period = observable(scene, run, "period");
    ASSERT_TRUE(period);
    const double expected = semi_implicit_euler_period(std::sqrt(1e5 / 0.5), dt);
    std::printf(
        "bullet/force at 1/240 s, k = 1e5: period %.5f s, %.3f of exact "
        "(semi-implicit Euler: %.3f)\n",
        *period, *period / exact, expected / exact);
    EXPECT_NEAR(*period, expected, 0.05 * expected);
  }
}

/// spring_pair's text with its spring's stiffness and the engine keys replaced.
Scene spring_pair_with(const std::string& stiffness, const std::string& engine_keys) {
  std::ifstream file(test::source_path("cases/spring_pair.toml"));
  std::stringstream text;
  text << file.rdbuf();
  std::string toml = text.str();
  const std::string k = "stiffness = 100.0";
  toml.replace(toml.find(k), k.size(), "stiffness = " + stiffness);
  return test::scene_from(toml + engine_keys);
}

// (b) The issue's numbers at 1/60 s: k = 1e4 N/m (w dt = 2.36, past semi-implicit Euler's
// limit of 2) swings sqrt(1e4 / 112.5) = 9.43 times too slowly with the limit, and blows up
// without it, as the hand force does.
TEST(BulletSprings, AtTenThousandTheLimitHoldsWhatWouldExplode) {
  const Backend* b = engine("bullet");
  BB_SKIP_IF_MISSING(test::not_built({"bullet"}));
  const Scene limited = spring_pair_with("1.0e4", "");
  const RunRecord run = run_accuracy(*b, limited, limited.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const std::optional<double> period = observable(limited, run, "period");
  ASSERT_TRUE(period);
  const double ratio = *period / two_mass_period(1e4);
  std::printf("bullet, k = 1e4 at 1/60 s: period %.4f s, %.3f times 2 pi sqrt(mu/k)\n", *period,
              ratio);
  EXPECT_NEAR(ratio, std::sqrt(1e4 / 112.5), 0.05 * std::sqrt(1e4 / 112.5));
  const Scene unlimited =
      spring_pair_with("1.0e4", "\n[engines.bullet]\nspring_limit_if_needed = false\n");
  EXPECT_EQ(run_accuracy(*b, unlimited, unlimited.report_dt).status, RunStatus::Diverged);
  if (const Backend* force = engine("bullet/force")) {
    EXPECT_EQ(run_accuracy(*force, limited, limited.report_dt).status, RunStatus::Diverged);
  }
}

// (b) The stiffness the joint used, read from the first step's velocity change
// (k' stretch dt / m), is the one engine_settings names.
TEST(BulletSprings, TheFirstStepShowsTheStiffnessTheSettingsName) {
  const Backend* b = engine("bullet");
  BB_SKIP_IF_MISSING(test::not_built({"bullet"}));
  const Scene scene = test::bundled_case("spring_pair_stiff");
  const double dt = scene.report_dt;
  auto sim = start_case(*b, scene, dt);
  sim->step();
  State state(2);
  sim->read(state);
  const double stretch = 1.001 - 1.0;
  const double used = state[0].velocity.x() * 1.0 / (stretch * dt);
  const double named = number_setting(sim->settings(), "spring_stiffness_used_max");
  std::printf("bullet, k = 1e5 at 1/240 s: first step's stiffness %.2f N/m, named %.2f N/m\n", used,
              named);
  EXPECT_NEAR(used, named, 1e-6 * named);
}

// (c) The run says how the springs are built, that sleeping is off and what the limit did.
TEST(BulletSprings, SettingsNameTheConstructionSleepingAndTheLimit) {
  const Scene scene = test::bundled_case("spring_pair");
  if (const Backend* b = engine("bullet")) {
    const Settings s = run_accuracy(*b, scene, scene.report_dt).engine_settings;
    EXPECT_NE(text_setting(s, "springs").find("btGeneric6DofSpring2Constraint"), std::string::npos);
    EXPECT_NE(text_setting(s, "spring_stiffness_limit").find("limitIfNeeded"), std::string::npos);
    EXPECT_NE(text_setting(s, "deactivation").find("DISABLE_DEACTIVATION"), std::string::npos);
    EXPECT_EQ(std::get<bool>(*setting(s, "sleeping")), false);
    EXPECT_EQ(std::get<bool>(*setting(s, "spring_limit_if_needed")), true);
    EXPECT_EQ(number_setting(s, "spring_stiffness_used_max"), 100.0);
    EXPECT_EQ(number_setting(s, "springs_stiffness_limited"), 0.0);
  }
  if (const Backend* b = engine("bullet/force")) {
    const Settings s = run_accuracy(*b, scene, scene.report_dt).engine_settings;
    EXPECT_NE(text_setting(s, "springs").find("applyCentralForce"), std::string::npos);
    EXPECT_NE(text_setting(s, "springs").find("no stiffness limit"), std::string::npos);
    EXPECT_EQ(std::get<bool>(*setting(s, "sleeping")), false);
  }
  if (const Backend* b = engine("bullet-softbody")) {
    const Settings s = run_accuracy(*b, scene, scene.report_dt).engine_settings;
    EXPECT_NE(text_setting(s, "springs").find("m_kLST"), std::string::npos);
    EXPECT_NE(text_setting(s, "spring_damping").find("kDP"), std::string::npos);
    EXPECT_NE(text_setting(s, "spring_stiffness_limit"), "");
    EXPECT_EQ(std::get<bool>(*setting(s, "sleeping")), false);
  }
}

// The key turns the limit off: the same stiff pair then swings near semi-implicit Euler's
// period, as the hand force does.
TEST(BulletSprings, TheLimitCanBeTurnedOff) {
  const Backend* b = engine("bullet");
  BB_SKIP_IF_MISSING(test::not_built({"bullet"}));
  std::ifstream file(test::source_path("cases/spring_pair_stiff.toml"));
  std::stringstream text;
  text << file.rdbuf();
  const Scene scene =
      test::scene_from(text.str() + "\n[engines.bullet]\nspring_limit_if_needed = false\n");
  const RunRecord run = run_accuracy(*b, scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const std::optional<double> period = observable(scene, run, "period");
  ASSERT_TRUE(period);
  const double expected = semi_implicit_euler_period(std::sqrt(1e5 / 0.5), scene.report_dt);
  std::printf("bullet, k = 1e5 without the limit: period %.5f s (semi-implicit Euler %.5f s)\n",
              *period, expected);
  EXPECT_NEAR(*period, expected, 0.05 * expected);
  EXPECT_EQ(number_setting(run.engine_settings, "spring_stiffness_used_max"), 1e5);
}

// A mass on a spring to an anchor, sent across the spring at 1 m/s without gravity.
const char* kAcross = R"(name = "across"
dims = 2
duration = 1.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "anchor"
shape = "point"
mass = 1.0
fixed = true
position = [0.0, 0.0, 0.0]
[[body]]
name = "mass"
shape = "point"
mass = 1.0
position = [1.0, 0.0, 0.0]
velocity = [0.0, 1.0, 0.0]
[[spring]]
bodies = ["anchor", "mass"]
stiffness = 100.0
rest_length = 1.0
)";

// What the settings' spring_axis says: the joint's spring is aimed along the line between
// the bodies before each step, so the mass sent across it circles the anchor on its spring
// (at 1 m/s the pull it needs, m v^2 / r = 1 N, stretches k = 100 N/m by a centimetre) as the
// hand force's does, instead of drifting off along its starting direction to 1.41 m.
TEST(BulletSprings, TheJointsSpringPullsAlongTheCurrentLine) {
  const Scene scene = test::scene_from(kAcross);
  for (const char* name : {"bullet", "bullet-float", "bullet/force"}) {
    const Backend* b = engine(name);
    if (b == nullptr) continue;
    const RunRecord run = run_accuracy(*b, scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << name << ": " << run.reason;
    double farthest = 0.0;
    for (const State& s : run.trajectory.states)
      farthest = std::max(farthest, s[1].position.norm());
    const Vec3 end = run.trajectory.states.back()[1].position;
    std::printf("%s: the mass ends at (%.4f, %.4f) m, at most %.4f m from the anchor\n", name,
                end.x(), end.y(), farthest);
    // The circle's stretch, a centimetre, and what the step's swing adds.
    EXPECT_LT(farthest, 1.05) << name;
    // A quarter turn of the circle or more in the second (1 m of arc at 1 m/s on r = 1 m).
    EXPECT_LT(end.x(), 0.9) << name;
  }
}

bool has_backend(const BackendSet& set, const std::string& name) {
  for (const Backend* b : set.all)
    if (b->name() == name) return true;
  return false;
}

// (d) The second ways of building springs take part in spring scenes only; the catalogue
// knows so even for plugins that were not built.
TEST(BulletSprings, SpringVariantsJoinOnlySpringScenes) {
  const Scene without = load_case(test::source_path("cases/drag_fall.toml"));
  const Scene with = test::bundled_case("spring_pair");
  const BackendSet plain = backends_for(without, registry());
  const BackendSet springs = backends_for(with, registry());
  for (const char* name : {"bullet/force", "bullet-softbody"}) {
    EXPECT_FALSE(has_backend(plain, name)) << name;
    if (engine(name) != nullptr) {
      EXPECT_TRUE(has_backend(springs, name)) << name;
    }
  }
  if (engine("bullet") != nullptr) {
    EXPECT_TRUE(has_backend(plain, "bullet"));
    EXPECT_TRUE(has_backend(springs, "bullet"));
  }
  for (const EngineDescription& e : engine_catalogue()) {
    if (e.engine != "bullet") continue;
    for (const char* name : {"bullet/force", "bullet-softbody"}) {
      ASSERT_NE(find_variant(e, name), nullptr) << name;
      EXPECT_TRUE(find_variant(e, name)->needs.has(Feature::Springs)) << name;
    }
  }
}

// (e) The soft body runs the sheets without crashing and their stretch is measured. (The
// anchors of every spring backend are tested in spring_variants_test.cpp.)
TEST(BulletSprings, TheSoftBodyRunsTheSheets) {
  const Backend* b = engine("bullet-softbody");
  BB_SKIP_IF_MISSING(test::not_built({"bullet-softbody"}));
  for (const char* name : {"sproing_2d", "cloth"}) {
    const Scene scene = test::bundled_case(name);
    const RunRecord run = run_accuracy(*b, scene, scene.report_dt);
    EXPECT_NE(run.status, RunStatus::Error) << name << ": " << run.reason;
    EXPECT_NE(run.status, RunStatus::Unsupported) << name << ": " << run.reason;
    const std::optional<double> stretch = observable(scene, run, "max_stretch");
    ASSERT_TRUE(stretch) << name;
    std::printf("bullet-softbody on %s: max_stretch %.4g\n", name, *stretch);
    EXPECT_TRUE(std::isfinite(*stretch)) << name;
  }
}

// The link stiffness mapping: one projection of a lone link is a backward-Euler step of
// the case's spring, so the pair swings with backward Euler's period, 2 pi dt / atan(w dt)
// (1.8% long at 1/60 s), and loses amplitude by 1 / sqrt(1 + (w dt)^2) every step.
TEST(BulletSprings, TheSoftBodyLinkIsBackwardEulerOfTheCasesSpring) {
  const Backend* b = engine("bullet-softbody");
  BB_SKIP_IF_MISSING(test::not_built({"bullet-softbody"}));
  const Scene scene = test::bundled_case("spring_pair");
  const double dt = scene.report_dt, w = std::sqrt(100.0 / 0.5);
  const RunRecord run = run_accuracy(*b, scene, dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const std::optional<double> period = observable(scene, run, "period");
  ASSERT_TRUE(period);
  const double expected = 2.0 * M_PI * dt / std::atan(w * dt);
  std::printf("bullet-softbody at 1/60 s: period %.5f s, backward Euler %.5f s, exact %.5f s\n",
              *period, expected, two_mass_period(100.0));
  // The crossing times' scatter, as in (a); PBD's length-squared error adds (0.1 / 1)^2.
  EXPECT_NEAR(*period, expected, 0.01 * expected);
  // After 1 s (60 steps) the amplitude is down to (1 + (w dt)^2)^-30 = 0.2 of 0.1 m; the
  // first swing of the second second peaks within half a period (13.6 steps) of that.
  State end(2);
  auto sim = start_case(*b, scene, dt);
  for (int k = 0; k < 60; ++k) sim->step();
  double largest = 0.0;
  for (int k = 0; k < 60; ++k) {
    sim->step();
    sim->read(end);
    largest = std::max(largest, std::abs((end[1].position - end[0].position).norm() - 1.0));
  }
  const double per_step = 1.0 / std::sqrt(1.0 + w * w * dt * dt);
  const double at_one_second = 0.1 * std::pow(per_step, 60.0);
  const double half_period_later = at_one_second * std::pow(per_step, expected / (2.0 * dt));
  std::printf(
      "bullet-softbody: largest stretch in the second second %.4f m (backward Euler "
      "%.4f m to %.4f m)\n",
      largest, half_period_later, at_one_second);
  EXPECT_LT(largest, 1.01 * at_one_second);
  EXPECT_GT(largest, 0.99 * half_period_later);
}

// The soft body refuses what it cannot hold: contacts.
TEST(BulletSprings, TheSoftBodyIsUnsupportedWithContacts) {
  const Backend* b = engine("bullet-softbody");
  BB_SKIP_IF_MISSING(test::not_built({"bullet-softbody"}));
  const Scene scene = load_case(test::source_path("cases/double_bounce.toml"));
  EXPECT_EQ(run_accuracy(*b, scene, scene.report_dt).status, RunStatus::Unsupported);
}

}  // namespace
}  // namespace bb
