// Every observable kind's event is set up by the one switch of EventWatches::add: a kind
// whose row names an event watches something, one that names none watches nothing, and an
// event no case of the switch handles is refused, never ignored.
#include "observe/event_watches.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace bb {
namespace {

/// Two balls on a ground, joined by a spring with a rest length: a world where every event
/// a kind can ask for has something to watch.
World two_balls_on_a_spring() {
  World world;
  world.ground = Ground{};
  world.bodies.resize(2);
  world.bodies[0].name = "a", world.bodies[1].name = "b";
  world.springs.push_back({.body_a = 0, .body_b = 1, .stiffness = 10.0, .rest_length = 1.0});
  return world;
}

/// An observe of `kind` on body 0 (or the whole scene), as the loader makes it.
Observe observe_of(const ObservableKind& kind) {
  Observe o;
  o.kind = kind.name;
  o.body = kind.scene_wide ? -1 : 0;
  o.name = kind.scene_wide ? kind.name : kind.name + "/a";
  if (kind.level) o.level = 1.0;
  return o;
}

TEST(EventWatches, EveryKindsEventIsSetUpByTheSwitch) {
  const World world = two_balls_on_a_spring();
  for (const ObservableKind& kind : observable_kind_table()) {
    const Observe o = observe_of(kind);
    EventWatches watches;
    ASSERT_NO_THROW(watches.add(world, o, kind)) << kind.name;
    EXPECT_EQ(watches == EventWatches{}, kind.event == WatchedEvent::None)
        << kind.name << ": a kind that names an event watches something, one that names "
        << "none watches nothing";
  }
}

TEST(EventWatches, AKindWatchesACrossingExactlyWhenItGivesItsValue) {
  for (const ObservableKind& kind : observable_kind_table())
    EXPECT_EQ(kind.event == WatchedEvent::Crossing, kind.crossing != nullptr) << kind.name;
}

TEST(EventWatches, AnEventNoCaseHandlesIsRefusedNotIgnored) {
  // An enumerator past the last, as one added to the enum and not to the switch would be.
  ObservableKind unhandled{.name = "new_kind"};
  unhandled.event = static_cast<WatchedEvent>(static_cast<int>(WatchedEvent::Crossing) + 1);
  EventWatches watches;
  EXPECT_THROW(watches.add(two_balls_on_a_spring(), observe_of(unhandled), unhandled),
               std::logic_error);
  // A crossing without the value it crosses with is refused too.
  ObservableKind bare{.name = "bare_crossing"};
  bare.event = WatchedEvent::Crossing;
  EXPECT_THROW(watches.add(two_balls_on_a_spring(), observe_of(bare), bare), std::logic_error);
}

TEST(EventWatches, ABodyIsWatchedOnceHoweverManyKindsAskAndAFallNeedsAGround) {
  World world = two_balls_on_a_spring();
  std::vector<Observe> observes;
  for (const char* kind : {"stop_time", "stop_distance", "rest_creep", "fall_time"}) {
    observes.push_back(observe_of(*observable_kind(kind)));
  }
  EXPECT_EQ(event_watches(world, observes).stopping, std::vector<int>{0});
  EXPECT_EQ(event_watches(world, observes).falling, std::vector<int>{0});
  world.ground.reset();
  EXPECT_TRUE(event_watches(world, observes).falling.empty());
  // Only the springs with a rest length stretch.
  world.springs.push_back({.body_a = 0, .body_b = 1, .stiffness = 10.0});
  EXPECT_EQ(event_watches(world, {observe_of(*observable_kind("max_stretch"))}).springs,
            std::vector<int>{0});
}

}  // namespace
}  // namespace bb
