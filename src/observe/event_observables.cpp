#include "observe/event_observables.hpp"

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

/// The first collision between two moving bodies, when the observed body took part in it;
/// else the note saying why there is none.
std::optional<ObservableValue> no_collision(const Observe& observe, const EventTrace& events) {
  const auto& c = events.first_collision;
  if (!c) return ObservableValue{std::nullopt, "no two moving bodies collided"};
  if (c->body_a != observe.body && c->body_b != observe.body)
    return ObservableValue{std::nullopt, "the first collision is between other bodies"};
  return std::nullopt;
}

}  // namespace

ObservableValue measure_contact_time(const Scene&, const Observe& observe, const Trajectory& t,
                                     const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  return b ? nth(b->contact_times, observe.n, "contacts") : kNoTrace;
}

ObservableValue measure_bounce_apex(const Scene&, const Observe& observe, const Trajectory& t,
                                    const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  return b ? nth(b->apex_heights, observe.n, "apexes after a contact") : kNoTrace;
}

ObservableValue measure_post_velocity(const Scene&, const Observe& observe, const Trajectory& t,
                                      const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  if (!b->post_velocity) return {std::nullopt, "the body touched nothing"};
  return {(*b->post_velocity).norm(), ""};
}

ObservableValue measure_post_normal_velocity(const Scene&, const Observe& observe,
                                             const Trajectory& t, const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  if (!b) return kNoTrace;
  if (!b->post_velocity) return {std::nullopt, "the body touched nothing"};
  return {b->post_velocity->dot(b->post_normal.value_or(Vec3::Zero())), ""};
}

ObservableValue measure_max_penetration(const Scene&, const Observe& observe, const Trajectory& t,
                                        const EventTrace*) {
  const BodyEvents* b = body_events(observe, t.events);
  return b ? ObservableValue{b->max_penetration, ""} : kNoTrace;
}

ObservableValue measure_period(const Scene&, const Observe& observe, const Trajectory& trajectory,
                               const EventTrace*) {
  const BodyEvents* b = body_events(observe, trajectory.events);
  if (!b) return kNoTrace;
  // The swing's axis: the one whose velocity crosses zero most often (a fall or a drift
  // never crosses), the widest swing among equals.
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    const std::size_t n = b->upward_crossings[k].size(), best = b->upward_crossings[axis].size();
    if (n > best || (n == best && b->velocity_range[k] > b->velocity_range[axis])) axis = k;
  }
  const std::vector<double>& t = b->upward_crossings[axis];
  if (t.size() < 2)
    return {std::nullopt, "fewer than two full swings in the run (" + std::to_string(t.size()) +
                              " upward zero crossings of the velocity)"};
  return {(t.back() - t.front()) / static_cast<double>(t.size() - 1), ""};
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

ObservableValue measure_momentum_change(const Scene&, const Observe& observe, const Trajectory& t,
                                        const EventTrace*) {
  if (auto none = no_collision(observe, t.events)) return *none;
  return {t.events.first_collision->momentum_change.norm(), ""};
}

ObservableValue measure_angular_momentum_change(const Scene&, const Observe& observe,
                                                const Trajectory& t, const EventTrace*) {
  if (auto none = no_collision(observe, t.events)) return *none;
  return {t.events.first_collision->angular_momentum_change.norm(), ""};
}

ObservableValue measure_energy_change(const Scene&, const Observe& observe, const Trajectory& t,
                                      const EventTrace*) {
  if (auto none = no_collision(observe, t.events)) return *none;
  const auto& c = *t.events.first_collision;
  return {c.kinetic_energy_after - c.kinetic_energy_before, ""};
}

}  // namespace bb
