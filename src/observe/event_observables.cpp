#include "observe/event_observables.hpp"

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "observe/hinge_observables.hpp"

namespace bb {

namespace {

/// The n-th (1-based) value of `values`, or a note saying how many there were.
ObservableValue nth(const std::vector<double>& values, int n, const char* what) {
  if (n >= 1 && static_cast<std::size_t>(n) <= values.size()) return {values[n - 1], ""};
  return {std::nullopt, "only " + std::to_string(values.size()) + " " + what + " in the run"};
}

/// The observed body's events, or nullptr when the run has none for it.
const BodyEvents* body_events(const Observe& observe, const EventTrace& events) {
  if (observe.body < 0 || static_cast<std::size_t>(observe.body) >= events.bodies.size())
    return nullptr;
  return &events.bodies[observe.body];
}

const ObservableValue kNoTrace{std::nullopt, "the run has no event trace"};
const ObservableValue kTouchedNothing{std::nullopt, "the body touched nothing"};

/// The note for a swing seen `count` times by `what` (fewer than two).
ObservableValue too_few_swings(std::size_t count, const std::string& what) {
  return {std::nullopt,
          "fewer than two full swings in the run (" + what + ": " + std::to_string(count) + ")"};
}

/// How wide a coordinate swings from its `turns`: the largest way between two turns in a row
/// (metres; 0 for fewer than two turns, as a fall or a drift has).
double widest_swing(const std::vector<Turn>& turns) {
  double widest = 0.0;
  for (std::size_t i = 1; i < turns.size(); ++i)
    widest = std::max(widest, std::abs(turns[i].position - turns[i - 1].position));
  return widest;
}

/// The lowest points of a coordinate from its `turns`, leaving out every turn
/// back by less than `least` (metres) from the turn kept before it (a wobble on the swing, a
/// float engine's rounding, a swing that has died away): of the turns the same way with only
/// such wobbles between them, the farthest stands for them all.
std::vector<Turn> lowest_turns(const std::vector<Turn>& turns, double least) {
  std::vector<Turn> kept;
  for (const Turn& t : turns) {
    if (!kept.empty() && kept.back().lowest == t.lowest) {
      const bool farther =
          t.lowest ? t.position < kept.back().position : t.position > kept.back().position;
      if (farther) kept.back() = t;
    } else if (kept.empty() || std::abs(t.position - kept.back().position) >= least) {
      kept.push_back(t);
    }
  }
  std::vector<Turn> out;
  for (const Turn& t : kept)
    if (t.lowest) out.push_back(t);
  return out;
}

/// The cycle of a coordinate that swings `swing` metres wide, from its lowest points `c`:
/// the mean of c[i + m].time - c[i].time over the whole groups of m, for the least number
/// m of them after which the swing comes back to the same point (each lowest point within
/// kPlaceShare of the swing of the one m before; a group seen twice at least, for m > 1);
/// the one span of two; nullopt for fewer, or where no m brings it back.
std::optional<double> repeating_cycle(const std::vector<Turn>& c, double swing) {
  if (c.size() < 2) return std::nullopt;
  for (std::size_t m = 1; m == 1 || 2 * m + 1 <= c.size(); ++m) {
    bool repeats = true;
    for (std::size_t i = 0; repeats && i + m < c.size(); ++i)
      repeats = std::abs(c[i + m].position - c[i].position) <= kPlaceShare * swing;
    const std::size_t cycles = (c.size() - 1) / m;
    if (repeats) return (c[m * cycles].time - c[0].time) / static_cast<double>(cycles);
  }
  return std::nullopt;
}

/// The mean time between `crossings` (`what` they are), or the note that there were
/// fewer than two.
ObservableValue mean_interval(const std::vector<double>& crossings, const std::string& what) {
  if (crossings.size() < 2) return too_few_swings(crossings.size(), what);
  return {(crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1), ""};
}

/// The first collision between two moving bodies, when the observed body took part in it;
/// else the note saying why there is none.
std::optional<ObservableValue> no_collision(const Scene& scene, const Observe& observe,
                                            const EventTrace& events) {
  const auto& c = events.first_collision;
  if (!c && static_cast<std::size_t>(observe.body) < events.bodies.size())
    if (auto why = unmeasured_contact(scene, observe.body, events.bodies[observe.body], true))
      return ObservableValue{std::nullopt, *why};
  if (!c) return ObservableValue{std::nullopt, "no two moving bodies collided"};
  if (c->body_a != observe.body && c->body_b != observe.body)
    return ObservableValue{std::nullopt, "the first collision is between other bodies"};
  return std::nullopt;
}

/// The note for a body whose first contact was seen only as a push, else `otherwise`.
ObservableValue untouched(const Scene& scene, int body, const BodyEvents& events,
                          const ObservableValue& otherwise) {
  if (auto why = unmeasured_contact(scene, body, events, false)) return {std::nullopt, *why};
  return otherwise;
}

}  // namespace

std::optional<std::string> unmeasured_contact(const Scene& scene, int body,
                                              const BodyEvents& events, bool with_moving) {
  const std::optional<UnresolvedContact>& u = events.unresolved_contact;
  if (!u || (with_moving && (u->other < 0 || scene.bodies[u->other].fixed))) return std::nullopt;
  const std::string other = u->other < 0 ? "the ground" : "'" + scene.bodies[u->other].name + "'";
  const std::string overlap =
      events.max_penetration > 0.0
          ? " (overlapping by up to " + short_number(events.max_penetration) + " m)"
          : "";
  return "not measured: from t = " + short_number(u->time) + " s the approach of '" +
         scene.bodies[body].name + "' and " + other + overlap + " slowed from " +
         short_number(u->approach_before) + " to " + short_number(u->approach_least) +
         " m/s, but at no step did they stop approaching: the backend pushed them apart over "
         "its steps (or held one inside the other) without a hit that can be timed";
}

ObservableValue measure_contact_time(const Scene& scene, const Observe& observe,
                                     const Trajectory& t, const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  const ObservableValue counted = nth(b->contact_times, observe.n, "contacts");
  return b->contact_times.empty() ? untouched(scene, observe.body, *b, counted) : counted;
}

ObservableValue measure_bounce_apex(const Scene&, const Observe& observe, const Trajectory& t,
                                    const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  return b ? nth(b->apex_heights, observe.n, "apexes after a contact") : kNoTrace;
}

ObservableValue measure_post_velocity(const Scene& scene, const Observe& observe,
                                      const Trajectory& t, const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  if (!b->post_velocity) return untouched(scene, observe.body, *b, kTouchedNothing);
  return {(*b->post_velocity).norm(), ""};
}

ObservableValue measure_post_normal_velocity(const Scene& scene, const Observe& observe,
                                             const Trajectory& t, const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  if (!b->post_velocity) return untouched(scene, observe.body, *b, kTouchedNothing);
  return {b->post_velocity->dot(b->post_normal.value_or(Vec3::Zero())), ""};
}

ObservableValue measure_max_penetration(const Scene&, const Observe& observe, const Trajectory& t,
                                        const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  return b ? ObservableValue{b->max_penetration, ""} : kNoTrace;
}

ObservableValue measure_period(const Scene& scene, const Observe& observe,
                               const Trajectory& trajectory, const EventTrace*) {
  const BodyEvents* b = body_events(observe, trajectory.events);
  if (!b) return kNoTrace;
  // A hinged body's cycle is its angle's.
  if (hinge_of(scene, observe.body) != nullptr)
    return mean_interval(b->hinge_crossings,
                         "upward zero crossings of its spin about the hinge's axis");
  // How wide each coordinate of the centre swings, a fall or a drift aside.
  Vec3 swing;
  for (int k = 0; k < 3; ++k) swing[k] = widest_swing(b->turns[k]);
  // The motion's own cycle: the longest of the cycles of the coordinates that swing at least
  // kSwingShare as wide as the widest, each from its lowest points (a pendulum's height goes
  // through two cycles in each of its swing's; past 90 degrees its swing across has three
  // lowest points in one).
  std::optional<double> longest;
  std::size_t most = 0;
  for (int k = 0; k < 3; ++k) {
    if (swing[k] < kSwingShare * swing.maxCoeff()) continue;
    const std::vector<Turn> lowest = lowest_turns(b->turns[k], kTurnShare * swing[k]);
    most = std::max(most, lowest.size());
    const std::optional<double> cycle = repeating_cycle(lowest, swing[k]);
    if (cycle && (!longest || *cycle > *longest)) longest = cycle;
  }
  if (longest) return {longest, ""};
  if (most < 2) return too_few_swings(most, "lowest points along any axis it swings on");
  return {std::nullopt,
          "its swing does not repeat: along no axis it swings on do its lowest points come "
          "back to the same place"};
}

ObservableValue measure_fall_time(const Scene&, const Observe& observe, const Trajectory& t,
                                  const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  if (!b->fall_time) return {std::nullopt, "it did not fall"};
  return {*b->fall_time, ""};
}

ObservableValue measure_max_stretch(const Scene&, const Observe&, const Trajectory& t,
                                    const EventTrace*) {
  if (!t.events.max_stretch) return kNoTrace;
  return {*t.events.max_stretch, ""};
}

ObservableValue measure_momentum_change(const Scene& scene, const Observe& observe,
                                        const Trajectory& t, const EventTrace*) {
  if (auto none = no_collision(scene, observe, t.events)) return *none;
  return {t.events.first_collision->momentum_change.norm(), ""};
}

ObservableValue measure_angular_momentum_change(const Scene& scene, const Observe& observe,
                                                const Trajectory& t, const EventTrace*) {
  if (auto none = no_collision(scene, observe, t.events)) return *none;
  return {t.events.first_collision->angular_momentum_change.norm(), ""};
}

ObservableValue measure_energy_change(const Scene& scene, const Observe& observe,
                                      const Trajectory& t, const EventTrace*) {
  if (auto none = no_collision(scene, observe, t.events)) return *none;
  const auto& c = *t.events.first_collision;
  return {c.kinetic_energy_after - c.kinetic_energy_before, ""};
}

}  // namespace bb
