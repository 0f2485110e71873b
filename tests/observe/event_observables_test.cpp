// Event observables read the n-th event, say why when there is none, and refuse to guess.
#include "observe/event_observables.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "observe/observable_registry.hpp"
#include "observe/observables.hpp"
#include "observe/step_observer.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

Observe of(const std::string& kind, int body, int n = 0) {
  Observe o;
  o.kind = kind, o.body = body, o.n = n;
  return o;
}

/// `o` measured through the registry on a run of one sample whose events are `t`.
std::optional<ObservableValue> measure_event(const Observe& o, const EventTrace& t) {
  Trajectory run;
  run.times = {0.0};
  run.states = {State(t.bodies.size())};
  run.events = t;
  return measure(Scene{}, o, run, nullptr);
}

TEST(EventObservables, CountedKindsReadTheNthEventOrSayHowManyThereWere) {
  EventTrace t;
  t.bodies.resize(2);
  t.bodies[0].contact_times = {1.0, 2.5};
  t.bodies[0].apex_heights = {6.08};
  t.bodies[0].post_velocity = Vec3{3.0, 4.0, 0.0};
  t.bodies[0].max_penetration = 0.02;
  EXPECT_EQ(*measure_event(of("contact_time", 0, 2), t)->value, 2.5);
  EXPECT_EQ(*measure_event(of("bounce_apex", 0, 1), t)->value, 6.08);
  const auto third = measure_event(of("contact_time", 0, 3), t);
  EXPECT_FALSE(third->value);
  EXPECT_NE(third->note.find("only 2 contacts"), std::string::npos);
  EXPECT_EQ(*measure_event(of("post_velocity", 0), t)->value, 5.0);
  EXPECT_EQ(*measure_event(of("max_penetration", 0), t)->value, 0.02);
  EXPECT_FALSE(measure_event(of("post_velocity", 1), t)->value);
  // A kind the registry does not hold says so rather than guessing.
  const auto unknown = measure_event(of("no_such_kind", 0), t);
  EXPECT_FALSE(unknown->value);
  EXPECT_NE(unknown->note.find("not measured by this version"), std::string::npos);
  EXPECT_EQ(observable_kind("contact_time")->measure, &measure_contact_time);
}

// post_normal_velocity has a direction: along the first contact's normal, which points away
// from what the body touched, positive for a body that bounced back or was pushed off,
// negative for one that went on into where the other was.
TEST(EventObservables, PostNormalVelocityIsSignedAlongTheContactNormal) {
  EventTrace t;
  t.bodies.resize(3);
  t.bodies[0].post_velocity = Vec3{3.0, 4.0, 0.0};
  t.bodies[0].post_normal = Vec3{0.0, 1.0, 0.0};
  t.bodies[1].post_velocity = Vec3{3.0, 4.0, 0.0};
  t.bodies[1].post_normal = Vec3{-1.0, 0.0, 0.0};
  EXPECT_EQ(*measure_event(of("post_normal_velocity", 0), t)->value, 4.0);
  EXPECT_EQ(*measure_event(of("post_normal_velocity", 1), t)->value, -3.0);
  const auto none = measure_event(of("post_normal_velocity", 2), t);
  EXPECT_FALSE(none->value);
  EXPECT_NE(none->note.find("touched nothing"), std::string::npos);
}

TEST(EventObservables, TheFirstCollisionsBalanceBelongsToItsTwoBodies) {
  EventTrace t;
  t.bodies.resize(3);
  t.first_collision = CollisionBalance{0, 1, 0.5, {0.0, 3.0, 4.0}, {0.0, 0.0, 2.0}, 10.0, 7.5};
  EXPECT_EQ(*measure_event(of("momentum_change", 1), t)->value, 5.0);
  EXPECT_EQ(*measure_event(of("energy_change", 0), t)->value, -2.5);
  EXPECT_FALSE(measure_event(of("energy_change", 2), t)->value);
}

/// The period observable of a pendulum of length 1 m swinging through theta = theta0
/// cos(2 pi t / T), T = 2 s, for 10 s: a point body, or a box hinged at the pivot (about z),
/// seen by the step observer every millisecond and sampled every 0.05 s. The swing's shape
/// is a stand-in for a pendulum's; the pattern of crossings is the same.
ObservableValue pendulum_period(double theta0_degrees, bool hinged) {
  const std::string body =
      hinged ? "shape = \"box\"\nhalf_extents = [0.05, 0.5, 0.05]\n" : "shape = \"point\"\n";
  const Scene scene = test::scene_from(
      "name = \"pendulum\"\ndims = 2\nduration = 10.0\nsample = 0.05\ndt = [0.001]\n"
      "[[body]]\nname = \"bob\"\nmass = 1.0\nposition = [0.0, -1.0, 0.0]\n" +
      body + (hinged ? "[[hinge]]\nbody = \"bob\"\nanchor = [0.0, 0.0, 0.0]\n" : "") +
      "[[observe]]\nkind = \"period\"\nbody = \"bob\"\n");
  const double theta0 = theta0_degrees * std::numbers::pi / 180.0, omega = std::numbers::pi;
  StepObserver observer(scene);
  Trajectory run;
  State s(1);
  for (int n = 0; n <= 10000; ++n) {
    const double t = n * 1e-3, theta = theta0 * std::cos(omega * t);
    const double spin = -theta0 * omega * std::sin(omega * t);
    s[0].position = {std::sin(theta), -std::cos(theta), 0.0};
    s[0].velocity = spin * Vec3(std::cos(theta), std::sin(theta), 0.0);
    s[0].angular_velocity = {0.0, 0.0, spin};
    s[0].orientation = Quat(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
    observer.observe(t, s);
    if (n % 50 == 0) run.times.push_back(t), run.states.push_back(s);
  }
  run.events = observer.trace();
  return measure(scene, scene.observes[0], run, nullptr);
}

// The period is the swing's whole cycle, T = 2 s, at small and large amplitude: not the
// height's, which goes through two cycles in each (its velocity crosses zero upwards at
// each passage through the bottom), nor, past 90 degrees, the swing across's three turns
// in one cycle; a hinged body's is its angle's.
TEST(EventObservables, ThePeriodIsTheSwingsWholeCycle) {
  for (const double theta0 : {5.0, 60.0, 120.0, 150.0})
    for (const bool hinged : {false, true}) {
      const ObservableValue period = pendulum_period(theta0, hinged);
      ASSERT_TRUE(period.value) << theta0 << " degrees: " << period.note;
      EXPECT_NEAR(*period.value, 2.0, 1e-6) << theta0 << " degrees, hinged " << hinged;
    }
}

// Lowest points that never come back to the same place give no period, and say so.
TEST(EventObservables, AnIrregularSwingHasNoPeriod) {
  EventTrace t;
  t.bodies.resize(1);
  // Lowest points at 0, 0.6 and 0.3 m, the highest between at 1 m: no place comes back.
  const double lows[] = {0.0, 0.6, 0.3};
  for (int k = 0; k < 3; ++k) {
    t.bodies[0].turns[0].push_back({2.0 * k, lows[k], true});
    t.bodies[0].turns[0].push_back({2.0 * k + 1.0, 1.0, false});
  }
  Trajectory run;
  run.times = {0.0, 1.0};
  run.states = {State(1), State(1)};
  run.states[1][0].position = {1.0, 0.0, 0.0};
  run.events = t;
  const ObservableValue period = measure(Scene{}, of("period", 0), run, nullptr);
  EXPECT_FALSE(period.value);
  EXPECT_NE(period.note.find("does not repeat"), std::string::npos) << period.note;
}

}  // namespace
}  // namespace bb
