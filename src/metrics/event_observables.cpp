#include "metrics/event_observables.hpp"

namespace bb {

namespace {

/// The n-th (1-based) value of `values`, or a note saying how many there were.
ObservableValue nth(const std::vector<double>& values, int n, const char* what) {
  if (n >= 1 && static_cast<std::size_t>(n) <= values.size()) return {values[n - 1], ""};
  return {std::nullopt, "only " + std::to_string(values.size()) + " " + what + " in the run"};
}

/// The mean time between upward zero crossings of the velocity along the axis it crosses
/// zero most often on (the swing's axis; a fall or a drift never crosses), the widest
/// swing among equals.
ObservableValue period(const BodyEvents& b) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    const std::size_t n = b.upward_crossings[k].size(), best = b.upward_crossings[axis].size();
    if (n > best || (n == best && b.velocity_range[k] > b.velocity_range[axis])) axis = k;
  }
  const std::vector<double>& t = b.upward_crossings[axis];
  if (t.size() < 2)
    return {std::nullopt, "fewer than two full swings in the run (" + std::to_string(t.size()) +
                              " upward zero crossings of the velocity)"};
  return {(t.back() - t.front()) / static_cast<double>(t.size() - 1), ""};
}

}  // namespace

std::optional<ObservableValue> measure_event(const Observe& observe, const EventTrace& events) {
  const std::string& kind = observe.kind;
  if (kind == "max_stretch") {
    if (!events.max_stretch) return ObservableValue{std::nullopt, "the run has no event trace"};
    return ObservableValue{*events.max_stretch, ""};
  }
  const bool body_kind = kind == "contact_time" || kind == "bounce_apex" ||
                         kind == "post_velocity" || kind == "post_normal_velocity" ||
                         kind == "max_penetration" || kind == "period" || kind == "fall_time";
  if (body_kind) {
    if (observe.body < 0 || static_cast<std::size_t>(observe.body) >= events.bodies.size())
      return ObservableValue{std::nullopt, "the run has no event trace"};
    const BodyEvents& b = events.bodies[observe.body];
    if (kind == "contact_time") return nth(b.contact_times, observe.n, "contacts");
    if (kind == "bounce_apex") return nth(b.apex_heights, observe.n, "apexes after a contact");
    if (kind == "max_penetration") return ObservableValue{b.max_penetration, ""};
    if (kind == "period") return period(b);
    if (kind == "fall_time") {
      if (!b.fall_time) return ObservableValue{std::nullopt, "it did not fall"};
      return ObservableValue{*b.fall_time, ""};
    }
    if (!b.post_velocity) return ObservableValue{std::nullopt, "the body touched nothing"};
    if (kind == "post_normal_velocity")
      return ObservableValue{b.post_velocity->dot(b.post_normal.value_or(Vec3::Zero())), ""};
    return ObservableValue{(*b.post_velocity).norm(), ""};
  }
  if (kind != "momentum_change" && kind != "energy_change" && kind != "angular_momentum_change")
    return std::nullopt;
  const auto& c = events.first_collision;
  if (!c) return ObservableValue{std::nullopt, "no two moving bodies collided"};
  if (c->body_a != observe.body && c->body_b != observe.body)
    return ObservableValue{std::nullopt, "the first collision is between other bodies"};
  if (kind == "momentum_change") return ObservableValue{c->momentum_change.norm(), ""};
  if (kind == "angular_momentum_change")
    return ObservableValue{c->angular_momentum_change.norm(), ""};
  return ObservableValue{c->kinetic_energy_after - c->kinetic_energy_before, ""};
}

}  // namespace bb
