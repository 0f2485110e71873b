// What a scene's observes ask to be watched as a run goes, beyond the samples: each kind's
// WatchedEvent (its registry row) set up in one switch, EventWatches::add, as Box2D's solver
// stages are one enum (b2SolverStageType) and one switch. The per-step observer
// (step_observer.hpp), the reference's events and peaks (reference/scene_model.cpp,
// peak_watch.cpp) and the report's stop panel read the lists it fills; none of them tests a
// kind. A kind that watches an event already in the enum is one file and one row; a new
// event is one enumerator and one case of the switch (the compiler names a case left out,
// and add() refuses a kind whose event no case set up).
#pragma once

#include <vector>

#include "model/world.hpp"
#include "observe/observable_measure.hpp"
#include "observe/observable_registry.hpp"
#include "seam/observes.hpp"

namespace bb {

/// An observe whose kind watches a value through zero, and that value's function.
struct CrossingWatch {
  const Observe* observe = nullptr;
  CrossingFn value = nullptr;
  bool operator==(const CrossingWatch&) const = default;
};

/// What is watched as a run goes, for the observes added; empty for a kind that watches
/// nothing (WatchedEvent::None). Bodies are listed once each, in the observes' order.
struct EventWatches {
  std::vector<int> swinging;     ///< bodies whose swings are timed (a period)
  std::vector<int> stopping;     ///< bodies whose stops along the ground are found
  std::vector<int> falling;      ///< bodies whose fall is timed (none without a ground)
  bool stretch = false;          ///< every spring's largest stretch is watched (max_stretch)
  std::vector<int> springs;      ///< when stretch: the springs with a rest length, which stretch
  std::vector<int> overlapping;  ///< bodies whose deepest overlap is watched
  std::vector<CrossingWatch> crossings;  ///< observes watching a value through zero

  /// Sets up what `observe`, of kind `kind`, watches in `world`: the one switch over
  /// WatchedEvent. Throws std::logic_error for an event no case of it sets up.
  void add(const World& world, const Observe& observe, const ObservableKind& kind);
  bool operator==(const EventWatches&) const = default;
};

/// What `observes` (of `world`) ask to be watched; an observe of a kind the registry does not
/// hold watches nothing.
EventWatches event_watches(const World& world, const std::vector<Observe>& observes);

}  // namespace bb
