// Event observables read the n-th event, say why when there is none, and refuse to guess.
#include "observe/event_observables.hpp"

#include <gtest/gtest.h>

#include "observe/observable_registry.hpp"
#include "observe/observables.hpp"

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

}  // namespace
}  // namespace bb
