#include "observe/event_watches.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace bb {

namespace {

/// Appends `body` to `bodies` unless it is there already.
void add_once(std::vector<int>& bodies, int body) {
  if (std::find(bodies.begin(), bodies.end(), body) == bodies.end()) bodies.push_back(body);
}

}  // namespace

void EventWatches::add(const World& world, const Observe& observe, const ObservableKind& kind) {
  // Every case returns: falling out of the switch is an event added to the enum and not here.
  switch (kind.event) {
    case WatchedEvent::None:
      return;
    case WatchedEvent::Swings:
      return add_once(swinging, observe.body);
    case WatchedEvent::Stops:
      return add_once(stopping, observe.body);
    case WatchedEvent::Falls:
      // A fall is the centre reaching its fallen height above the ground: none without one.
      if (world.ground) add_once(falling, observe.body);
      return;
    case WatchedEvent::Stretch:
      if (stretch) return;
      stretch = true;
      for (int k = 0; k < static_cast<int>(world.springs.size()); ++k)
        if (world.springs[k].rest_length > 0.0) springs.push_back(k);
      return;
    case WatchedEvent::Overlap:
      return add_once(overlapping, observe.body);
    case WatchedEvent::Crossing:
      if (kind.crossing == nullptr)
        throw std::logic_error("observable kind '" + kind.name +
                               "' watches a crossing but gives no CrossingFn");
      crossings.push_back({&observe, kind.crossing});
      return;
  }
  throw std::logic_error("observable kind '" + kind.name + "' watches event " +
                         std::to_string(static_cast<int>(kind.event)) +
                         ", which no case of EventWatches::add sets up");
}

EventWatches event_watches(const World& world, const std::vector<Observe>& observes) {
  EventWatches watches;
  for (const Observe& o : observes)
    if (const ObservableKind* kind = observable_kind(o.kind)) watches.add(world, o, *kind);
  return watches;
}

}  // namespace bb
