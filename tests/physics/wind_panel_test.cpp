// The wind panel (seed section 8, "Wind") through the force model: the push against its
// formula square-on, edge-on and at an angle, for the text's linear law and the flat plate's
// quadratic one, and its derivative against finite differences; the reference's height
// wobbles with half the spin's period whatever the spin; and the reference's energy changes
// by the work the wind does on the panel.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/motion.hpp"
#include "observe/observable_registry.hpp"
#include "physics/energy.hpp"
#include "physics/force_model.hpp"
#include "physics/state_forces.hpp"
#include "run/accuracy_run.hpp"
#include "support/engine_support.hpp"
#include "support/jacobian_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// One 1 kg panel, 1 m by 1 m (its thin axis x), turned `angle` degrees about z and spinning
/// at `spin` rad/s, in a wind of 8 m/s along x, its push by `plate` (the [body.plate] lines);
/// numbers written to round-trip.
std::string panel_case(const std::string& plate, double angle = 0.0, double spin = 0.0,
                       double duration = 1.0, double sample = 0.1) {
  return "name = \"panel\"\ndims = 2\nduration = " + fmt::format("{}", duration) +
         "\nsample = " + fmt::format("{}", sample) + "\ndt = [" + fmt::format("{}", sample) +
         "]\nreport_dt = " + fmt::format("{}", sample) +
         "\n[air]\ndensity = 1.2\nwind = [8.0, 0.0, 0.0]\n[[body]]\nname = \"panel\"\n"
         "shape = \"box\"\nhalf_extents = [0.01, 0.5, 0.5]\nmass = 1.0\nangle = " +
         std::to_string(angle) + "\nangular_velocity = [0.0, 0.0, " + std::to_string(spin) +
         "]\n[body.plate]\n" + plate + "\n";
}

/// The force model's push on the panel moving at `velocity` (gravity is not among its terms).
Vec3 push_on(const Scene& scene, const Vec3& velocity) {
  State s = initial_state(scene);
  s[0].velocity = velocity;
  return StateForces(scene).at(s).force[0];
}

const std::string kCourse = "law = \"course\"\nk = 4.0";
const std::string kQuadratic = "law = \"quadratic\"\ncoefficient = 1.2";

TEST(WindPanel, ThePushIsAlongTheNormalSquareOnNoneEdgeOnAndByEachLawBetween) {
  // Square on (normal along the wind): k a w, and 1/2 rho C a w^2.
  EXPECT_NEAR(push_on(test::scene_from(panel_case(kCourse)), Vec3::Zero()).x(), 4.0 * 8.0, 1e-12);
  EXPECT_NEAR(push_on(test::scene_from(panel_case(kQuadratic)), Vec3::Zero()).x(),
              0.5 * 1.2 * 1.2 * 64.0, 1e-12);
  // Edge on (normal across the wind): nothing.
  for (const std::string& law : {kCourse, kQuadratic})
    EXPECT_LT(push_on(test::scene_from(panel_case(law, 90.0)), Vec3::Zero()).norm(), 1e-12);
  // At 30 degrees, moving at (2, 1): along n = (cos 30, sin 30), by (v_a . n) or its square.
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Vec3 n(c, s, 0.0), v(2.0, 1.0, 0.0);
  const double along = (Vec3(8.0, 0.0, 0.0) - v).dot(n);
  EXPECT_LT((push_on(test::scene_from(panel_case(kCourse, 30.0)), v) - 4.0 * along * n).norm(),
            1e-12);
  EXPECT_LT((push_on(test::scene_from(panel_case(kQuadratic, 30.0)), v) -
             0.5 * 1.2 * 1.2 * along * std::abs(along) * n)
                .norm(),
            1e-12);
  // A panel moving faster than the wind is pushed back: the wind relative to it, not plus it.
  EXPECT_LT(push_on(test::scene_from(panel_case(kCourse)), Vec3(10.0, 0.0, 0.0)).x(), 0.0);
}

TEST(WindPanel, ItsDerivativeMatchesFiniteDifferences) {
  for (const std::string& law : {kCourse, kQuadratic}) {
    SCOPED_TRACE(law);
    const Scene scene = test::scene_from(panel_case(law, 30.0));
    State s = initial_state(scene);
    s[0].velocity = Vec3(2.0, 1.0, 0.0);
    test::expect_velocity_derivative_matches(
        scene, s, [&](const Vec3& v) { return push_on(scene, v); }, 1e-6);
  }
}

/// The reference's wobble_period of the panel spinning at `spin` under `law`.
ObservableValue reference_wobble_period(const std::string& law, double spin) {
  const Scene scene = test::scene_from(panel_case(law, 0.0, spin, 8.0, 1.0 / 64.0));
  const RunRecord run = run_accuracy(test::registry().reference(), scene, scene.sample, false);
  EXPECT_EQ(run.status, RunStatus::Ok) << run.reason;
  Observe observe;
  observe.kind = "wobble_period";
  observe.body = 0;
  return observable_kind("wobble_period")->measure(scene, observe, run.trajectory, nullptr);
}

double reference_wobble(const std::string& law, double spin) {
  const ObservableValue v = reference_wobble_period(law, spin);
  EXPECT_TRUE(v.value) << v.note;
  return v.value.value_or(0.0);
}

TEST(WindPanel, TheHeightWobblesWithHalfTheSpinsPeriod) {
  for (const std::string& law : {kCourse, kQuadratic})
    for (double spin : {4.0, 6.0}) {
      SCOPED_TRACE(law + ", spin " + std::to_string(spin));
      // Upward crossings interpolated between samples 1/64 s apart: within 1e-3 s.
      EXPECT_NEAR(reference_wobble(law, spin), std::numbers::pi / spin, 1e-3);
    }
}

// A panel that catches too little wind to stop speeding up has no steady fall to take out:
// no period, with the reason, rather than one read off a fall that is still changing.
TEST(WindPanel, AFallThatIsNotSteadyHasNoWobblePeriod) {
  const ObservableValue v = reference_wobble_period("law = \"course\"\nk = 0.02", 4.0);
  EXPECT_FALSE(v.value) << *v.value;
  EXPECT_NE(v.note.find("not steady"), std::string::npos) << v.note;
}

TEST(WindPanel, TheReferencesEnergyChangesByTheWorkOfTheWind) {
  // Sampled finely, Simpson's rule sums the wind's power F . v to 1e-8 of the work.
  const Scene scene = test::scene_from(panel_case(kCourse, 20.0, 4.0, 2.0, 1.0 / 1024.0));
  const RunRecord run = run_accuracy(test::registry().reference(), scene, scene.sample, false);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const std::vector<State>& states = run.trajectory.states;
  const auto power = [&](const State& s) {
    const Vec3 n = s[0].orientation * Vec3::UnitX();
    return 4.0 * (Vec3(8.0, 0.0, 0.0) - s[0].velocity).dot(n) * n.dot(s[0].velocity);
  };
  // Simpson's rule over the 2048 equal intervals.
  ASSERT_EQ(states.size() % 2, 1u);
  double work = 0.0;
  for (std::size_t j = 1; j + 1 < states.size(); j += 2)
    work +=
        (power(states[j - 1]) + 4.0 * power(states[j]) + power(states[j + 1])) * scene.sample / 3.0;
  const double change = total_energy(scene, states.back()) - total_energy(scene, states.front());
  EXPECT_GT(std::abs(work), 1.0);
  EXPECT_NEAR(change, work, 1e-8 * std::abs(work));
}

}  // namespace
}  // namespace bb
