#include "observe/step_observer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/motion.hpp"
#include "observe/event_watches.hpp"
#include "observe/hinge_observables.hpp"
#include "observe/stop_observables.hpp"

namespace bb {

double spin_turn(const BodyState& before, const BodyState& now, double h,
                 std::optional<double> kicked) {
  return kicked ? before.angular_velocity.z() * *kicked + now.angular_velocity.z() * (h - *kicked)
                : 0.5 * (before.angular_velocity.z() + now.angular_velocity.z()) * h;
}

double next_turn(double turn, double spun, const BodyState& now) {
  const double angle = angle_about_z(now.orientation), whole = 2.0 * std::numbers::pi;
  return angle + whole * std::round((turn + spun - angle) / whole);
}

Vec3 along_ground(const Scene& scene, const Vec3& v) {
  if (!scene.ground) return v;
  return v - v.dot(scene.ground->normal) * scene.ground->normal;
}

StepObserver::StepObserver(const Scene& scene)
    : scene_(scene),
      pairs_(contact_pairs(scene)),
      closing_(pairs_.size(), 0.0),
      normals_(pairs_.size(), Eigen::Vector3d::Zero()),
      rising_(scene.bodies.size(), false),
      bounced_(scene.bodies.size(), false),
      episodes_(pairs_.size()),
      post_owner_(scene.bodies.size(), -1) {
  trace_.bodies.resize(scene.bodies.size());
  // What the observes' kinds watch, each kind's event set up in EventWatches::add's switch.
  const EventWatches events = event_watches(scene, scene.observes);
  swinging_ = events.swinging;
  for (int body : swinging_) swing_hinge_.push_back(hinge_of(scene, body));
  stopping_ = events.stopping;
  falling_ = events.falling;
  for (const CrossingWatch& w : events.crossings) {
    crossing_watches_.push_back({w});
    trace_.crossings[w.observe->name];
  }
  fastest_.assign(stopping_.size(), 0.0);
  for (int body : stopping_) rest_speeds_.push_back(stated_rest_speed(scene, body));
  watches_.assign(stopping_.size(), StopWatch{});
  watch_stretch_ = events.stretch;
  if (watch_stretch_) {
    trace_.max_stretch = 0.0;
    stretched_ = events.springs;
    last_stretch_.resize(stretched_.size());
  }
  // A 2D body turns when it spins at the start, is pushed, touches something or hangs on a
  // hinge; nothing else in a scene exerts a torque.
  turning_.assign(scene.bodies.size(), 0);
  turns_.assign(scene.bodies.size(), 0.0);
  if (scene.dims != 2) return;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    turning_[i] = scene.bodies[i].angular_velocity.norm() > 0.0;
  for (const Impulse& i : scene.impulses) turning_[i.body] = 1;
  for (const Hinge& h : scene.hinges) turning_[h.body] = 1;
  for (const ContactPair& p : pairs_) {
    turning_[p.a] = 1;
    if (!p.ground()) turning_[p.b] = 1;
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    if (b.fixed || b.shape == Shape::Point) turning_[i] = 0;
    watch_turns_ = watch_turns_ || turning_[i];
  }
}

void StepObserver::write_turns(State& state) const {
  if (scene_.dims != 2) return;
  for (std::size_t i = 0; i < state.size(); ++i)
    state[i].turn = turning_[i] ? turns_[i] : angle_about_z(state[i].orientation);
}

void StepObserver::observe_swings(double t, const State& s) {
  const double h = t - previous_t_;
  // Upwards through zero: negative at the last step, not at this one. Linear
  // interpolation: a sine is straight near its zero, so the crossing is placed to third
  // order in the step, whatever the integrator staggers.
  const auto upward = [&](double before, double now, std::vector<double>& crossings) {
    if (before < 0.0 && now >= 0.0) crossings.push_back(previous_t_ + h * before / (before - now));
  };
  // A coordinate's turn: its velocity through zero either way, placed as above; the
  // coordinate there on the straight line between the steps.
  const auto turn = [&](int i, int axis, std::vector<Turn>& turns) {
    const double before = previous_[i].velocity[axis], now = s[i].velocity[axis];
    const bool lowest = before < 0.0 && now >= 0.0;
    if (!lowest && !(before > 0.0 && now <= 0.0)) return;
    const double f = before / (before - now);
    turns.push_back(
        {previous_t_ + f * h,
         previous_[i].position[axis] + f * (s[i].position[axis] - previous_[i].position[axis]),
         lowest});
  };
  for (std::size_t k = 0; k < swinging_.size(); ++k) {
    const int i = swinging_[k];
    BodyEvents& e = trace_.bodies[i];
    if (const Hinge* hinge = swing_hinge_[k]) {
      // A hinged body's cycle is its angle's: the spin about the axis.
      upward(previous_[i].angular_velocity.dot(hinge->axis), s[i].angular_velocity.dot(hinge->axis),
             e.hinge_crossings);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) turn(i, axis, e.turns[axis]);
  }
}

void StepObserver::observe_stops(double t, const State& s) {
  const double h = t - previous_t_, g_step = scene_.gravity.norm() * h;
  for (std::size_t k = 0; k < stopping_.size(); ++k) {
    const int i = stopping_[k];
    const Vec3 now = along_ground(scene_, s[i].velocity);
    BodyEvents& e = trace_.bodies[i];
    StopWatch& w = watches_[k];
    if (first_) {
      fastest_[k] = std::max(fastest_[k], now.norm());
      continue;
    }
    const Vec3 before = along_ground(scene_, previous_[i].velocity);
    const double rest = rest_speeds_[k].value_or(kRestShare * std::max(fastest_[k], g_step));
    const bool was_at_rest = before.norm() <= rest, at_rest = now.norm() <= rest;
    // The start, judged with the first step's levels: at rest there (stopped at t = 0, a
    // rest as long as any), or in a motion from there.
    if (previous_t_ == 0.0 && was_at_rest) {
      w.resting = 2;
      e.stop_time = 0.0, e.stop_position = e.motion_start = previous_[i].position;
    } else if (previous_t_ == 0.0) {
      w.moving = true;
      w.begin = previous_[i].position;
      w.largest = before.norm();
    }
    // At rest: setting off after two observations at rest or more begins a motion there,
    // and the body has not stopped until it ends; so does setting off faster than any
    // motion so far (a push right after a float engine's jitter came to rest), where a
    // crawl after a stop does not.
    bool set_off = false;
    if (!w.moving) {
      if (at_rest) {
        ++w.resting;
      } else if (w.resting >= 2 || now.norm() > w.largest) {
        w.moving = true;
        set_off = true;
        w.begin = previous_[i].position;
        e.stop_time.reset();
      } else {
        w.resting = 0;
      }
    }
    if (w.moving) {
      w.largest = std::max(w.largest, now.norm());
      // Came to rest, or turned back (not a step that set off against a jitter's
      // direction): the stop is when the speed along the old direction reaches zero on
      // the line through the two steps, within the step for a turn, at most a step past it
      // for a body still moving at rest speed. Its place: within the step for a turn; for
      // a body come to rest, where it is now (what it moves after that is its rest_creep;
      // a place on the line past this step would overshoot a slide that eases to a stop).
      if (!was_at_rest && !set_off && (at_rest || now.dot(before) < 0.0)) {
        const double along = now.dot(before) / before.norm();
        const double f = std::min(2.0, before.norm() / (before.norm() - along));
        w.moving = false;
        w.resting = at_rest ? 1 : 0;
        e.stop_time = previous_t_ + f * h;
        e.stop_position =
            previous_[i].position + std::min(f, 1.0) * (s[i].position - previous_[i].position);
        e.motion_start = w.begin;
      }
    }
    fastest_[k] = std::max(fastest_[k], now.norm());
  }
}

void StepObserver::observe_falls(double t, const State& s) {
  const Ground& g = *scene_.ground;
  for (int i : falling_) {
    BodyEvents& e = trace_.bodies[i];
    const double level = fallen_height(scene_.bodies[i].half_extents);
    const double now = (s[i].position - g.point).dot(g.normal) - level;
    const double before = (previous_[i].position - g.point).dot(g.normal) - level;
    if (e.fall_time || now > 0.0 || before <= 0.0) continue;
    e.fall_time = previous_t_ + (t - previous_t_) * before / (before - now);
  }
}

void StepObserver::observe_crossings(double t, const State& s) {
  for (CrossingState& c : crossing_watches_) {
    const Observe& o = *c.watch.observe;
    const double now = c.watch.value(scene_, o, s[o.body]), before = c.last;
    c.last = now;
    if (first_) continue;
    // Up when it leaves below zero, down when it leaves above: as the reference's events.
    const bool rising = before < 0.0 && now >= 0.0, falling = before > 0.0 && now <= 0.0;
    if (rising || falling)
      trace_.crossings[o.name].push_back(
          {previous_t_ + (t - previous_t_) * before / (before - now), rising});
  }
}

void StepObserver::observe_stretch(double h, const State& s) {
  double& largest = *trace_.max_stretch;
  for (std::size_t k = 0; k < stretched_.size(); ++k) {
    const Spring& spring = scene_.springs[stretched_[k]];
    const BodyState &a = s[spring.body_a], &b = s[spring.body_b];
    const Stretch now =
        spring_stretch(a.position, b.position, a.velocity, b.velocity, spring.rest_length);
    largest = std::max(largest, now.value);
    // Turned from growing to shrinking since the last step: the peak lies between.
    const Stretch& before = last_stretch_[k];
    if (!first_ && before.rate > 0.0 && now.rate < 0.0)
      largest = std::max(largest, hermite_peak(before.value, before.rate, now.value, now.rate, h));
    last_stretch_[k] = now;
  }
}

void StepObserver::observe_apexes(double dt, const State& s) {
  // Apexes: a body that bounced stops rising above the ground.
  const Eigen::Vector3d n = scene_.ground->normal, ground = scene_.ground->point;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (scene_.bodies[i].fixed) continue;
    const bool rising = s[i].velocity.dot(n) > 0.0;
    if (!first_ && rising_[i] && !rising && bounced_[i]) {
      // The apex lies between the two steps: the peak of the cubic through their heights
      // and vertical speeds (the flight's own parabola, where nothing but gravity acts).
      const double now = (s[i].position - ground).dot(n);
      const double before = (previous_[i].position - ground).dot(n);
      trace_.bodies[i].apex_heights.push_back(
          hermite_peak(before, previous_[i].velocity.dot(n), now, s[i].velocity.dot(n), dt));
      bounced_[i] = false;
    }
    rising_[i] = rising;
  }
}

std::optional<double> StepObserver::kick_in_step(std::size_t i, double t) const {
  // An impulse lands at its time: at the start of the step it rounds to (a fixed step), or
  // inside the interval (the reference between its samples); the case makes its time a
  // multiple of every dt.
  const double h = t - previous_t_, slack = 1e-9 * h;
  for (const Impulse& imp : scene_.impulses)
    if (imp.body == static_cast<int>(i) && imp.time >= previous_t_ - slack && imp.time < t - slack)
      return std::max(0.0, imp.time - previous_t_);
  return std::nullopt;
}

void StepObserver::observe(double t, const State& s) {
  if (!active()) return;
  const double dt = t - previous_t_;
  // The turn about z of each body that can turn, unwrapped from its spin at every step.
  if (watch_turns_)
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!turning_[i]) continue;
      if (first_) {
        turns_[i] = angle_about_z(s[i].orientation);
        continue;
      }
      const double spun = spin_turn(previous_[i], s[i], dt, kick_in_step(i, t));
      const double expected = turns_[i] + spun;
      turns_[i] = next_turn(turns_[i], spun, s[i]);
      // Where the orientation and the spin disagree by more than a quarter turn, which whole
      // turn the step made is a guess: said, not counted.
      std::optional<double>& unclear = trace_.bodies[i].turn_unclear;
      if (!unclear && std::abs(turns_[i] - expected) > 0.5 * std::numbers::pi) unclear = t;
    }
  if (!first_ && !falling_.empty()) observe_falls(t, s);
  if (!first_ && !swinging_.empty()) observe_swings(t, s);
  if (!stopping_.empty()) observe_stops(t, s);
  if (!crossing_watches_.empty()) observe_crossings(t, s);
  if (watch_stretch_) observe_stretch(dt, s);
  if (!pairs_.empty()) observe_contacts(t, dt, s);
  if (scene_.ground) observe_apexes(dt, s);
  previous_ = s;
  previous_t_ = t;
  first_ = false;
}

}  // namespace bb
