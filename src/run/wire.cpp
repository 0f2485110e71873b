#include "run/wire.hpp"

#include <cstring>
#include <stdexcept>

namespace bb::wire {

namespace {

class Writer {
 public:
  template <typename T>
  void raw(const T& v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void text(const std::string& s) {
    raw<std::uint64_t>(s.size());
    bytes_ += s;
  }
  void maybe(const std::optional<double>& v) {
    raw<char>(v.has_value());
    raw<double>(v.value_or(0.0));
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T raw() {
    if (at_ + sizeof(T) > bytes_.size())
      throw std::runtime_error("truncated result from a child process");
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string text() {
    const auto n = raw<std::uint64_t>();
    if (at_ + n > bytes_.size()) throw std::runtime_error("truncated result from a child process");
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  std::optional<double> maybe() {
    const bool has = raw<char>() != 0;
    const double v = raw<double>();
    return has ? std::optional<double>(v) : std::nullopt;
  }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

void put(Writer& w, const Vec3& v) {
  w.raw(v.x()), w.raw(v.y()), w.raw(v.z());
}
Vec3 get_vec(Reader& r) {
  const double x = r.raw<double>(), y = r.raw<double>(), z = r.raw<double>();
  return {x, y, z};
}

void put(Writer& w, const std::vector<double>& values) {
  w.raw<std::uint64_t>(values.size());
  for (double v : values) w.raw(v);
}
std::vector<double> get_values(Reader& r) {
  std::vector<double> out(r.raw<std::uint64_t>());
  for (double& v : out) v = r.raw<double>();
  return out;
}

void put(Writer& w, const EventTrace& events) {
  w.raw<std::uint64_t>(events.bodies.size());
  for (const BodyEvents& b : events.bodies) {
    put(w, b.contact_times), put(w, b.apex_heights);
    w.raw<char>(b.post_velocity.has_value());
    if (b.post_velocity) put(w, *b.post_velocity), put(w, b.post_normal.value_or(Vec3::Zero()));
    w.raw(b.max_penetration);
    w.raw<char>(b.unresolved_contact.has_value());
    if (const auto& u = b.unresolved_contact)
      w.raw(u->other), w.raw(u->time), w.raw(u->approach_before), w.raw(u->approach_least);
    for (const std::vector<Turn>& turns : b.turns) {
      w.raw<std::uint64_t>(turns.size());
      for (const Turn& turn : turns) w.raw(turn.time), w.raw(turn.position), w.raw(turn.lowest);
    }
    put(w, b.hinge_crossings);
    w.raw<char>(b.stop_time.has_value());
    if (b.stop_time) w.raw(*b.stop_time), put(w, b.stop_position), put(w, b.motion_start);
    w.raw<char>(b.fall_time.has_value());
    if (b.fall_time) w.raw(*b.fall_time);
    w.raw<char>(b.turn_unclear.has_value());
    if (b.turn_unclear) w.raw(*b.turn_unclear);
  }
  w.raw<char>(events.first_collision.has_value());
  if (const auto& c = events.first_collision) {
    w.raw(c->body_a), w.raw(c->body_b), w.raw(c->time), put(w, c->momentum_change);
    put(w, c->angular_momentum_change);
    w.raw(c->kinetic_energy_before), w.raw(c->kinetic_energy_after);
  }
  w.raw<char>(events.max_stretch.has_value());
  if (events.max_stretch) w.raw(*events.max_stretch);
  w.raw<std::uint64_t>(events.crossings.size());
  for (const auto& [name, crossings] : events.crossings) {
    w.text(name);
    w.raw<std::uint64_t>(crossings.size());
    for (const Crossing& c : crossings) w.raw(c.time), w.raw(c.rising);
  }
}
EventTrace get_events(Reader& r) {
  EventTrace events;
  events.bodies.resize(r.raw<std::uint64_t>());
  for (BodyEvents& b : events.bodies) {
    b.contact_times = get_values(r), b.apex_heights = get_values(r);
    if (r.raw<char>()) b.post_velocity = get_vec(r), b.post_normal = get_vec(r);
    b.max_penetration = r.raw<double>();
    if (r.raw<char>()) {
      UnresolvedContact u;
      u.other = r.raw<int>(), u.time = r.raw<double>();
      u.approach_before = r.raw<double>(), u.approach_least = r.raw<double>();
      b.unresolved_contact = u;
    }
    for (std::vector<Turn>& turns : b.turns) {
      turns.resize(r.raw<std::uint64_t>());
      for (Turn& turn : turns)
        turn.time = r.raw<double>(), turn.position = r.raw<double>(), turn.lowest = r.raw<bool>();
    }
    b.hinge_crossings = get_values(r);
    if (r.raw<char>())
      b.stop_time = r.raw<double>(), b.stop_position = get_vec(r), b.motion_start = get_vec(r);
    if (r.raw<char>()) b.fall_time = r.raw<double>();
    if (r.raw<char>()) b.turn_unclear = r.raw<double>();
  }
  if (r.raw<char>()) {
    CollisionBalance c;
    c.body_a = r.raw<int>(), c.body_b = r.raw<int>();
    c.time = r.raw<double>(), c.momentum_change = get_vec(r);
    c.angular_momentum_change = get_vec(r);
    c.kinetic_energy_before = r.raw<double>(), c.kinetic_energy_after = r.raw<double>();
    events.first_collision = c;
  }
  if (r.raw<char>()) events.max_stretch = r.raw<double>();
  for (auto n = r.raw<std::uint64_t>(); n > 0; --n) {
    std::vector<Crossing>& crossings = events.crossings[r.text()];
    crossings.resize(r.raw<std::uint64_t>());
    for (Crossing& c : crossings) c.time = r.raw<double>(), c.rising = r.raw<bool>();
  }
  return events;
}

}  // namespace

std::string encode(const RunRecord& run) {
  Writer w;
  w.text(run.backend);
  w.maybe(run.dt);
  w.raw<int>(static_cast<int>(run.status));
  w.text(run.reason);
  w.maybe(run.diverged_at);
  w.raw<long>(run.steps);
  w.raw<std::uint64_t>(run.engine_settings.size());
  for (const auto& [key, value] : run.engine_settings) {
    w.text(key);
    w.raw<int>(static_cast<int>(value.index()));
    if (const auto* d = std::get_if<double>(&value)) w.raw(*d);
    if (const auto* b = std::get_if<bool>(&value)) w.raw<char>(*b);
    if (const auto* s = std::get_if<std::string>(&value)) w.text(*s);
  }
  const Trajectory& t = run.trajectory;
  // Times, then the states kept (none, or a few bodies', or all of them).
  put(w, t.times);
  w.raw<std::uint64_t>(t.states.size());
  w.raw<std::uint64_t>(t.states.empty() ? 0 : t.states.front().size());
  for (const State& state : t.states)
    for (const BodyState& b : state) {
      put(w, b.position), put(w, b.velocity), put(w, b.angular_velocity);
      w.raw(b.orientation.w()), w.raw(b.orientation.x()), w.raw(b.orientation.y()),
          w.raw(b.orientation.z());
      w.raw(b.turn);
    }
  put(w, t.events);
  // What the child measured against the reference, if it did.
  w.raw<char>(run.errors.has_value());
  if (const auto& e = run.errors) {
    w.raw(e->position_max), w.raw(e->position_rms), w.raw(e->position_final);
    w.raw(e->velocity_max), w.raw(e->energy_max);
    w.raw<std::uint64_t>(e->bodies.size());
    for (const BodyErrors& b : e->bodies)
      w.raw(b.position_max), w.raw(b.position_rms), w.raw(b.position_final), w.raw(b.velocity_max);
  }
  w.raw<std::uint64_t>(run.observables.size());
  for (const ObservableResult& o : run.observables) {
    w.text(o.name);
    w.maybe(o.measured.value);
    w.text(o.measured.note);
    w.maybe(o.reference);
  }
  put(w, run.energy);
  put(w, run.distance);
  w.raw(run.position_scale);
  w.raw(run.travel);
  w.raw<char>(run.summarised);
  w.text(run.messages);
  w.raw<char>(run.stability_trial.has_value());
  if (const auto& t = run.stability_trial) w.text(encode(*t));
  w.text(run.trajectory_problem);
  w.raw(run.step_seconds);
  return w.take();
}

RunRecord decode_run(const std::string& bytes) {
  Reader r(bytes);
  RunRecord run;
  run.backend = r.text();
  run.dt = r.maybe();
  run.status = static_cast<RunStatus>(r.raw<int>());
  run.reason = r.text();
  run.diverged_at = r.maybe();
  run.steps = r.raw<long>();
  const auto settings = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < settings; ++i) {
    std::string key = r.text();
    const int kind = r.raw<int>();
    if (kind == 0) run.engine_settings.push_back({key, r.raw<double>()});
    if (kind == 1) run.engine_settings.push_back({key, r.raw<char>() != 0});
    if (kind == 2) run.engine_settings.push_back({key, r.text()});
  }
  run.trajectory.times = get_values(r);
  const auto samples = r.raw<std::uint64_t>();
  const auto bodies = r.raw<std::uint64_t>();
  for (std::uint64_t j = 0; j < samples; ++j) {
    State state(bodies);
    for (BodyState& b : state) {
      b.position = get_vec(r), b.velocity = get_vec(r), b.angular_velocity = get_vec(r);
      const double w = r.raw<double>(), x = r.raw<double>(), y = r.raw<double>(),
                   z = r.raw<double>();
      b.orientation = {w, x, y, z};
      b.turn = r.raw<double>();
    }
    run.trajectory.states.push_back(std::move(state));
  }
  run.trajectory.events = get_events(r);
  if (r.raw<char>()) {
    ErrorMetrics e;
    e.position_max = r.raw<double>(), e.position_rms = r.raw<double>();
    e.position_final = r.raw<double>(), e.velocity_max = r.raw<double>();
    e.energy_max = r.raw<double>();
    e.bodies.resize(r.raw<std::uint64_t>());
    for (BodyErrors& b : e.bodies) {
      b.position_max = r.raw<double>(), b.position_rms = r.raw<double>();
      b.position_final = r.raw<double>(), b.velocity_max = r.raw<double>();
    }
    run.errors = e;
  }
  run.observables.resize(r.raw<std::uint64_t>());
  for (ObservableResult& o : run.observables) {
    o.name = r.text();
    o.measured.value = r.maybe();
    o.measured.note = r.text();
    o.reference = r.maybe();
  }
  run.energy = get_values(r);
  run.distance = get_values(r);
  run.position_scale = r.raw<double>();
  run.travel = r.raw<double>();
  run.summarised = r.raw<char>() != 0;
  run.messages = r.text();
  if (r.raw<char>()) run.stability_trial = decode_trial(r.text());
  run.trajectory_problem = r.text();
  run.step_seconds = r.raw<double>();
  return run;
}

std::string encode(const std::vector<RunRecord>& runs) {
  Writer w;
  w.raw<std::uint64_t>(runs.size());
  for (const RunRecord& run : runs) w.text(encode(run));
  return w.take();
}

std::vector<RunRecord> decode_runs(const std::string& bytes) {
  Reader r(bytes);
  std::vector<RunRecord> out(r.raw<std::uint64_t>());
  for (RunRecord& run : out) run = decode_run(r.text());
  return out;
}

std::string encode(const std::vector<Timing>& timings) {
  Writer w;
  w.raw<std::uint64_t>(timings.size());
  for (const Timing& t : timings)
    w.raw(t.median_seconds), w.raw(t.repeats), w.raw(t.calls_timed), w.raw(t.min_seconds),
        w.raw(t.max_seconds), w.raw(t.timed_seconds), w.raw(t.builds);
  return w.take();
}

std::vector<Timing> decode_timings(const std::string& bytes) {
  Reader r(bytes);
  std::vector<Timing> out(r.raw<std::uint64_t>());
  for (Timing& t : out) {
    t.median_seconds = r.raw<double>();
    t.repeats = r.raw<int>();
    t.calls_timed = r.raw<long>();
    t.min_seconds = r.raw<double>();
    t.max_seconds = r.raw<double>();
    t.timed_seconds = r.raw<double>();
    t.builds = r.raw<int>();
  }
  return out;
}

std::string encode(const StabilityTrial& trial) {
  Writer w;
  w.raw<char>(trial.stable);
  w.text(trial.reason);
  w.text(trial.growth);
  w.raw(trial.step_seconds);
  return w.take();
}

StabilityTrial decode_trial(const std::string& bytes) {
  Reader r(bytes);
  StabilityTrial t;
  t.stable = r.raw<char>() != 0;
  t.reason = r.text();
  t.growth = r.text();
  t.step_seconds = r.raw<double>();
  return t;
}

}  // namespace bb::wire
