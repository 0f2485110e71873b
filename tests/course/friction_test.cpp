// The course's friction (seed section 6): the naive rule overshoots zero and crawls, the
// two fixes stop the block; the rules' forces as properties of one step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "course/course_backend.hpp"
#include "course/friction_rules.hpp"
#include "observe/step_observer.hpp"
#include "observe/stop_observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using course::Coulomb;
using course::FrictionRule;
using Eigen::Vector3d;

RunRecord run_rule(const Scene& scene, const std::string& rule, const std::string& integrator) {
  const CourseBackend backend({"course/" + integrator + "+" + rule, integrator, "clamp", rule});
  return run_accuracy(backend, scene, scene.report_dt);
}

/// `kind`/`body` of `run`, measured against the reference's events.
std::optional<double> observed(const Scene& scene, const RunRecord& run, const RunRecord& ref,
                               const std::string& kind, const std::string& body) {
  const Observe o{kind, scene.body_index(body), 0, 0, kind + "/" + body};
  return measure(scene, o, run.trajectory, &ref.trajectory.events).value;
}

// The seed's demo: after the stop, naive crawls (it carries the velocity past zero, and
// the next step's friction throws it back); clamp does not move at all, low-speed no more
// than rounding. For each block, each Euler.
TEST(CourseFriction, NaiveCreepsAfterTheStopAndBothFixesDoNot) {
  const Scene scene = load_case(test::source_path("cases/sliding_block.toml"));
  const RunRecord ref = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(ref.status, RunStatus::Ok) << ref.reason;
  for (const std::string integrator : {"explicit-euler", "semi-implicit-euler"})
    for (const std::string body : {"slow", "medium", "fast"}) {
      const auto naive =
          observed(scene, run_rule(scene, "naive", integrator), ref, "rest_creep", body);
      const auto clamp =
          observed(scene, run_rule(scene, "clamp", integrator), ref, "rest_creep", body);
      const auto low =
          observed(scene, run_rule(scene, "low-speed", integrator), ref, "rest_creep", body);
      ASSERT_TRUE(naive && clamp && low) << integrator << " " << body;
      std::printf("%s %s: creep naive %.4g m, clamp %.3g m, low-speed %.3g m\n", integrator.c_str(),
                  body.c_str(), *naive, *clamp, *low);
      // A crawl of millimetres to centimetres over the rest of the run...
      EXPECT_GT(*naive, 1e-3) << integrator << " " << body;
      // ...where clamp stands still and low-speed's one capped step leaves rounding.
      EXPECT_EQ(*clamp, 0.0) << integrator << " " << body;
      EXPECT_LT(*low, 1e-12) << integrator << " " << body;
    }
}

// Semi-implicit Euler with the low-speed cap gives the discrete answer for a 1 kg
// box at 5 m/s with mu = 0.5 at 1/60 s: the steps v -= mu g dt, x += v dt, until the one
// that would reverse v, which the cap turns into v = 0 (step 62, 1.0333 s, 2.50685 m).
TEST(CourseFriction, LowSpeedEndsTheSlideOnTheStepThatWouldReverseIt) {
  const Scene scene = load_case(test::source_path("cases/sliding_block.toml"));
  const RunRecord run = run_rule(scene, "low-speed", "semi-implicit-euler");
  const int medium = scene.body_index("medium");
  const double dt = scene.report_dt, a = 0.5 * 9.81 * dt;
  double v = 5.0, x = 0.0;
  int steps = 0;
  while (v - a > 0.0) v -= a, x += v * dt, ++steps;
  // The capped step brings v to zero: x does not change on it.
  ASSERT_TRUE(run.trajectory.events.bodies[medium].stop_time);
  EXPECT_NEAR(*run.trajectory.events.bodies[medium].stop_time, (steps + 1) * dt, 1e-12);
  const Vector3d start = scene.bodies[medium].position;
  EXPECT_NEAR((run.trajectory.events.bodies[medium].stop_position - start).x(), x, 1e-12);
  EXPECT_NEAR(x, 2.50685, 1e-5);
}

// On a slope that holds (tan 28 = 0.53 below mu_s = 0.6, above mu_k = 0.5), every rule
// holds the block: it starts at rest, where static friction takes the slope's pull.
TEST(CourseFriction, EveryRuleHoldsTheBlockOnSlopeHold) {
  const Scene scene = load_case(test::source_path("cases/slope_hold.toml"));
  for (const std::string rule : {"naive", "clamp", "low-speed"}) {
    const RunRecord run = run_rule(scene, rule, "semi-implicit-euler");
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    const Vec3 moved =
        run.trajectory.states.back()[0].position - run.trajectory.states.front()[0].position;
    EXPECT_LT(moved.norm(), 1e-15) << rule;
  }
}

/// A 1 kg, 1 m cube sliding at `speed` m/s on a ground tilted by `slope` degrees (falling
/// away to +x), sent downhill, mu_s 0.6 and mu_k 0.5, for `duration` s at 1/60 s; the case
/// has no [course] section, as a user writes it, so the ground rule is the default.
Scene sliding_block(double speed, double slope, double duration) {
  const double a = slope * std::numbers::pi / 180.0;
  const Vector3d n(std::sin(a), std::cos(a), 0.0), along(std::cos(a), -std::sin(a), 0.0);
  const auto num = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return std::string(text);
  };
  const auto vec = [&](const Vector3d& v) {
    return "[" + num(v.x()) + ", " + num(v.y()) + ", 0.0]";
  };
  return test::scene_from(
      "name = \"slide\"\ndims = 2\nduration = " + std::to_string(duration) +
      "\nsample = 0.0166666666666666667\ndt = [0.0166666666666666667]\n"
      "report_dt = 0.0166666666666666667\n[ground]\nnormal = " +
      vec(n) +
      "\nfriction_static = 0.6\nfriction_kinetic = 0.5\n[[body]]\nname = \"block\"\n"
      "shape = \"box\"\nhalf_extents = [0.5, 0.5, 0.5]\nmass = 1.0\nposition = " +
      vec(0.5 * n) + "\nangle = " + num(-slope) + "\nvelocity = " + vec(speed * along) +
      "\n[[observe]]\nkind = \"stop_time\"\nbody = \"block\"\n"
      "[[observe]]\nkind = \"stop_distance\"\nbody = \"block\"\n");
}

/// The course variant with `integrator`, `ground` rule and `friction` rule on `scene`.
RunRecord run_variant(const Scene& scene, const std::string& integrator, const std::string& ground,
                      const std::string& friction) {
  const CourseBackend backend({"course/" + integrator, integrator, ground, friction});
  return run_accuracy(backend, scene, scene.report_dt);
}

/// How far `body` of `run` went along the ground from its start by time t (interpolated
/// between the samples around t).
double slid_by(const Scene& scene, const RunRecord& run, double t) {
  const Trajectory& tr = run.trajectory;
  for (std::size_t j = 0; j + 1 < tr.times.size(); ++j) {
    if (t > tr.times[j + 1]) continue;
    const double f = (t - tr.times[j]) / (tr.times[j + 1] - tr.times[j]);
    const Vec3 x = (1.0 - f) * tr.states[j][0].position + f * tr.states[j + 1][0].position;
    return along_ground(scene, x - scene.bodies[0].position).norm();
  }
  return std::nan("");
}

const char* const kIntegrators[] = {"explicit-euler", "semi-implicit-euler", "velocity-verlet",
                                    "rk4"};

// Friction acts on a body in contact whatever the ground rule: the block on level ground
// slides v0^2 / (2 mu_k g) = 2.548 m in v0 / (mu_k g) = 1.019 s under every integrator,
// ground rule and friction rule, to 2 %. The seed's naive rule may crawl after the stop (by
// design): for it the distance is read at the closed form's stop time; the two fixes stop
// the block there and keep it there.
TEST(CourseFriction, FrictionActsUnderEveryGroundRule) {
  const double v0 = 5.0, mu = 0.5, g = 9.81;
  const double distance = v0 * v0 / (2.0 * mu * g), time = v0 / (mu * g);
  const Scene scene = sliding_block(v0, 0.0, 2.0);
  for (const char* integrator : kIntegrators)
    for (const std::string ground : {"reflect", "clamp", "mirror"})
      for (const std::string rule : {"naive", "clamp", "low-speed"}) {
        const std::string what = std::string(integrator) + " + " + ground + " + " + rule;
        const RunRecord run = run_variant(scene, integrator, ground, rule);
        ASSERT_EQ(run.status, RunStatus::Ok) << what << ": " << run.reason;
        EXPECT_NEAR(slid_by(scene, run, time), distance, 0.02 * distance) << what;
        if (rule == "naive") continue;
        const auto stop = measure(scene, scene.observes[1], run.trajectory, nullptr).value;
        ASSERT_TRUE(stop) << what;
        EXPECT_NEAR(*stop, distance, 0.02 * distance) << what;
        EXPECT_NEAR(slid_by(scene, run, scene.duration), distance, 0.02 * distance) << what;
      }
}

// The clamp rule stops the block for every integrator: on level ground and going down a
// 20 degree slope (tan 20 = 0.36, below mu_s = 0.6, so static friction holds it once
// stopped; mu_k = 0.5 decelerates it by g (mu_k cos 20 - sin 20) = 1.255 m/s^2), from 5 m/s.
// Verlet and RK4 approach zero without crossing it within a step, so a rule that waits for
// the velocity to cross zero never fires for them (they crawled at 0.028 and 0.008 m/s): the
// block must be still at the end, having stopped within a step of the closed form's time
// and 2 % of its distance.
TEST(CourseFriction, ClampStopsTheBlockWithEveryIntegratorOnLevelGroundAndASlope) {
  const double g = 9.81;
  for (const double slope : {0.0, 20.0}) {
    const double a = slope * std::numbers::pi / 180.0;
    const double decel = g * (0.5 * std::cos(a) - std::sin(a)), v0 = 5.0;
    const Scene scene = sliding_block(v0, slope, 5.0);
    for (const char* integrator : kIntegrators) {
      const std::string what = std::string(integrator) + " at " + std::to_string(slope) + " deg";
      const RunRecord run = run_variant(scene, integrator, "clamp", "clamp");
      ASSERT_EQ(run.status, RunStatus::Ok) << what << ": " << run.reason;
      // Still along the ground (explicit Euler rests with -g dt along the normal between two
      // resolutions): rounding at most.
      const Vec3 end = run.trajectory.states.back()[0].velocity;
      EXPECT_LT(along_ground(scene, end).norm(), 1e-12) << what;
      const auto stop_time = measure(scene, scene.observes[0], run.trajectory, nullptr).value;
      const auto stop_distance = measure(scene, scene.observes[1], run.trajectory, nullptr).value;
      ASSERT_TRUE(stop_time && stop_distance) << what;
      EXPECT_NEAR(*stop_time, v0 / decel, scene.report_dt) << what;
      EXPECT_NEAR(*stop_distance, v0 * v0 / (2.0 * decel), 0.02 * v0 * v0 / (2.0 * decel)) << what;
    }
  }
}

// A 2 kg block at rest pushed by 6 N s at 0.5 s (mu_k 0.3): its stop is the end of that
// slide, at 0.5 + v0 / (mu_k g) = 1.519 s from the start of the run after v0^2 / (2 mu_k g)
// = 1.529 m from where the push found it, for every integrator with the clamp rule; and it
// creeps nothing after the reference's stop.
TEST(CourseFriction, ABlockPushedFromRestStopsWhereItsSlideEnds) {
  const Scene scene = test::scene_from(test::pushed_block_case(
      "[[impulse]]\nbody = \"block\"\ntime = 0.5\nimpulse = [6.0, 0.0, 0.0]\n"));
  const double mu_g = 0.3 * 9.81, time = 0.5 + 3.0 / mu_g, distance = 9.0 / (2.0 * mu_g);
  const RunRecord ref = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(ref.status, RunStatus::Ok) << ref.reason;
  for (const char* integrator : kIntegrators) {
    const RunRecord run = run_variant(scene, integrator, "mirror", "clamp");
    ASSERT_EQ(run.status, RunStatus::Ok) << integrator << ": " << run.reason;
    const auto stop_time = observed(scene, run, ref, "stop_time", "block");
    const auto stop_distance = observed(scene, run, ref, "stop_distance", "block");
    const auto creep = observed(scene, run, ref, "rest_creep", "block");
    ASSERT_TRUE(stop_time && stop_distance && creep) << integrator;
    EXPECT_NEAR(*stop_time, time, scene.report_dt) << integrator;
    EXPECT_NEAR(*stop_distance, distance, 0.02 * distance) << integrator;
    EXPECT_EQ(*creep, 0.0) << integrator;
  }
}

// One step's friction, as a property over random states: kinetic friction opposes the
// sliding velocity with mu_k N; at rest, static friction holds up to mu_s N exactly and
// lets go just beyond; the low-speed cap never lets one explicit step reverse the velocity.
TEST(CourseFriction, OneStepsForceObeysCoulomb) {
  const Coulomb c{0.6, 0.5};
  const Vector3d n = Vector3d(0.3, 1.0, -0.2).normalized();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<> u(-3.0, 3.0);
  const double dt = 1.0 / 60.0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d g(u(rng), -9.81, u(rng));
    const Vector3d v = course::tangential(Vector3d(u(rng), u(rng), u(rng)), n);
    const double press = -g.dot(n);
    const Vector3d kinetic = course::with_friction(FrictionRule::Naive, c, n, v, g, dt) - g;
    EXPECT_NEAR(kinetic.norm(), 0.5 * press, 1e-12);
    EXPECT_NEAR(kinetic.normalized().dot(v.normalized()), -1.0, 1e-12);
    // The capped friction alone, over one explicit step, never turns v back.
    const Vector3d capped = course::with_friction(FrictionRule::LowSpeed, c, n, v, g, dt) - g;
    EXPECT_GE((v + dt * capped).dot(v), -1e-12 * v.squaredNorm());
  }
  // At rest: held exactly while the pull along the plane is at most mu_s N.
  const Vector3d up = Vector3d::UnitY();
  const Vector3d holds(0.6 * 9.81, -9.81, 0.0), slips(0.6 * 9.81 * (1 + 1e-9), -9.81, 0.0);
  EXPECT_EQ(course::with_friction(FrictionRule::Clamp, c, up, Vector3d::Zero(), holds, dt),
            Vector3d(0.0, -9.81, 0.0));
  const Vector3d slipping =
      course::with_friction(FrictionRule::Clamp, c, up, Vector3d::Zero(), slips, dt);
  EXPECT_NEAR(slipping.x(), slips.x() - 0.5 * 9.81, 1e-12);
}

}  // namespace
}  // namespace bb
