#include "metrics/event_observables.hpp"

namespace bb {

namespace {

/// The n-th (1-based) value of `values`, or a note saying how many there were.
ObservableValue nth(const std::vector<double>& values, int n, const char* what) {
  if (n >= 1 && static_cast<std::size_t>(n) <= values.size()) return {values[n - 1], ""};
  return {std::nullopt, "only " + std::to_string(values.size()) + " " + what + " in the run"};
}

}  // namespace

std::optional<ObservableValue> measure_event(const Observe& observe, const EventTrace& events) {
  const std::string& kind = observe.kind;
  const bool body_kind = kind == "contact_time" || kind == "bounce_apex" ||
                         kind == "post_velocity" || kind == "max_penetration";
  if (body_kind) {
    if (observe.body < 0 || static_cast<std::size_t>(observe.body) >= events.bodies.size())
      return ObservableValue{std::nullopt, "the run has no event trace"};
    const BodyEvents& b = events.bodies[observe.body];
    if (kind == "contact_time") return nth(b.contact_times, observe.n, "contacts");
    if (kind == "bounce_apex") return nth(b.apex_heights, observe.n, "apexes after a contact");
    if (kind == "max_penetration") return ObservableValue{b.max_penetration, ""};
    if (!b.post_velocity) return ObservableValue{std::nullopt, "the body touched nothing"};
    return ObservableValue{(*b.post_velocity).norm(), ""};
  }
  if (kind != "momentum_change" && kind != "energy_change") return std::nullopt;
  const auto& c = events.first_collision;
  if (!c) return ObservableValue{std::nullopt, "no two moving bodies collided"};
  if (c->body_a != observe.body && c->body_b != observe.body)
    return ObservableValue{std::nullopt, "the first collision is between other bodies"};
  if (kind == "momentum_change") return ObservableValue{c->momentum_change.norm(), ""};
  return ObservableValue{c->kinetic_energy_after - c->kinetic_energy_before, ""};
}

}  // namespace bb
