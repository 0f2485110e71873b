// The reference's events and resets: the gap of each contact pair, apexes and swings as
// event functions, the step bound that keeps a thin body from being stepped through, and
// what a contact or an impulse does to the state (Newton's restitution, resting contact).
#include <cmath>
#include <limits>

#include "contact/contact_geometry.hpp"
#include "contact/impulse_response.hpp"
#include "contact/rigid_hit.hpp"
#include "model/motion.hpp"
#include "physics/hinge_motion.hpp"
#include "reference/gsl_reference.hpp"
#include "reference/scene_model.hpp"
#include "reference/scene_model_state.hpp"
#include "reference/sliding_modes.hpp"

namespace bb {

namespace {

using namespace state_view;

}  // namespace

contact::Proximity SceneModel::proximity(const ContactPair& pair, const double* y) const {
  const int b = pair.ground() ? pair.a : pair.b;
  return contact::measure(scene_, pair, position(y, pair.a), position(y, b), orientation(y, b));
}

void SceneModel::events(double, const double* y, double* g) {
  for (std::size_t k = 0; k < sources_.size(); ++k) g[k] = event_value(sources_[k], y);
}

double SceneModel::event_value(const Source& s, const double* y) const {
  switch (s.watch) {
    case Watch::HingeSwing:
      // Falls through zero when the spin about the hinge's axis rises through zero.
      return -spin(y, s.body).dot(hinge_[s.body]->axis);
    case Watch::Swing: {
      // Falls through zero when the velocity component rises through zero (or, watching it
      // go down, falls through zero).
      const double v = velocity(y, s.body)[s.axis];
      return s.down ? v : -v;
    }
    case Watch::Stop: {
      // The speed along the direction of sliding falls through zero at the stop.
      const SlideDecision& slide = slides_[s.body];
      const bool sliding = resting_[s.body] && slide.mode == SlideMode::Sliding;
      return sliding ? velocity(y, s.body).dot(slide.direction) : 1.0;
    }
    case Watch::Apex: {
      // The normal velocity falling through zero after a bounce is the apex.
      const bool watching = after_bounce_[s.body] && !resting_[s.body];
      return watching ? velocity(y, s.body).dot(scene_.ground->normal) : 1.0;
    }
    case Watch::Fall: {
      // The centre's height falls through the height of lying flat.
      const Vector3d above = Vector3d(position(y, s.body)) - scene_.ground->point;
      return above.dot(scene_.ground->normal) - fallen_height(scene_.bodies[s.body].half_extents);
    }
    case Watch::Crossing: {
      // The kind's value falls through zero (or, watching it rise, rises through zero).
      const double v = s.crossing(scene_, s.observe, body_state(y, s.body));
      return s.down ? v : -v;
    }
    case Watch::Contact:
      break;
  }
  if (s.pair.ground() && resting_[s.pair.a]) return 1.0;
  if (s.pair.ground() && lands(s.pair.a)) {
    // A hinged box's corners off its axis reaching the ground; held, it watches nothing.
    const int i = s.pair.a;
    const Hinge& h = *hinge_[i];
    return hinge_held_[i] ? 1.0
                          : contact::clear_height(position(y, i), orientation(y, i),
                                                  scene_.bodies[i].half_extents, h.anchor, h.axis,
                                                  scene_.ground->point, scene_.ground->normal);
  }
  return proximity(s.pair, y).gap;
}

double SceneModel::max_step(double, const double* y) {
  // The thickness a body presents to a contact: a sphere's diameter, a box's thinnest side.
  const auto thickness = [&](int i) {
    const Body& b = scene_.bodies[i];
    if (b.shape == Shape::Sphere) return 2.0 * b.radius;
    if (b.shape == Shape::Box) return 2.0 * b.half_extents.minCoeff();
    return 0.0;
  };
  double limit = std::numeric_limits<double>::infinity();
  for (const Source& s : sources_) {
    if (!s.contact() || s.pair.ground()) continue;
    const double speed = (Vector3d(velocity(y, s.pair.a)) - Vector3d(velocity(y, s.pair.b))).norm();
    const double region = thickness(s.pair.a) + thickness(s.pair.b);
    if (speed > 0.0 && region > 0.0) limit = std::min(limit, 0.25 * region / speed);
  }
  return limit;
}

Vector3d SceneModel::momentum(const double* y) const {
  Vector3d p = Vector3d::Zero();
  for (int i = 0; i < static_cast<int>(scene_.bodies.size()); ++i)
    if (!scene_.bodies[i].fixed) p += scene_.bodies[i].mass * velocity(y, i);
  return p;
}

void SceneModel::check_simultaneous(const ContactPair& pair, const double* y, double t) const {
  for (const Source& other : sources_) {
    const ContactPair& o = other.pair;
    if (!other.contact() || (o.a == pair.a && o.b == pair.b)) continue;
    const bool shares =
        o.a == pair.a || o.a == pair.b || o.b == pair.a || (o.b >= 0 && o.b == pair.b);
    if (!shares || (o.ground() && resting_[o.a])) continue;
    if (proximity(o, y).gap <= kSimultaneousGap)
      throw BeyondExactAnswer(
          "at t = " + std::to_string(t) + " s body '" + scene_.bodies[pair.a].name +
          "' touches two things at once: simultaneous contacts have no exact answer here");
  }
}

void SceneModel::record_hit(const ContactPair& pair, const Vector3d& normal, const double* y,
                            double t, bool b_moves) {
  for (int body : {pair.a, b_moves ? pair.b : -1}) {
    if (body < 0) continue;
    BodyEvents& e = trace_.bodies[body];
    e.contact_times.push_back(t);
    // The normal points from the second shape to the first: away from b for a.
    if (!e.post_velocity)
      e.post_velocity = Vector3d(velocity(y, body)),
      e.post_normal = body == pair.a ? Vector3d(normal) : Vector3d(-normal);
    after_bounce_[body] = true;
  }
}

void SceneModel::lift_resting(const ContactPair& pair, const double* y, double t) {
  for (int body : {pair.a, pair.b}) {
    if (body < 0 || !resting_[body]) continue;
    // An impulse may lift a resting body off the ground, but not press it in.
    const double up = velocity(y, body).dot(scene_.ground->normal);
    if (up < 0.0)
      throw BeyondExactAnswer("at t = " + std::to_string(t) + " s body '" +
                              scene_.bodies[body].name +
                              "' is pushed into the ground while resting on it");
    resting_[body] = up <= 0.0;
    if (!resting_[body]) slides_[body] = {};
  }
}

void SceneModel::end_small_bounce(const ContactPair& pair, double gap, double* y, double t) {
  // Ever smaller bounces end: a rebound this short leaves the body resting on the ground.
  const Vector3d n = scene_.ground->normal;
  const double pull = -scene_.gravity.dot(n);
  const double rebound = velocity(y, pair.a).dot(n);
  if (pull > 0.0 && 2.0 * rebound / pull < rest_flight_time()) {
    if (scene_.bodies[pair.a].shape == Shape::Sphere &&
        (pair.friction_static > 0.0 || pair.friction_kinetic > 0.0))
      throw BeyondExactAnswer("at t = " + std::to_string(t) + " s ball '" +
                              scene_.bodies[pair.a].name +
                              "' comes to rest on a ground with friction: it would roll, and "
                              "rolling has no model in the reference");
    resting_[pair.a] = true;
    after_bounce_[pair.a] = false;
    Vec(y + at(pair.a) + 3) -= rebound * n;
    Vec(y + at(pair.a)) -= gap * n;
    settle(pair.a, y, t);
  }
}

void SceneModel::resolve(const ContactPair& pair, double* y, double t) {
  const bool ground = pair.ground();
  const contact::Proximity p = proximity(pair, y);
  const auto hit_body = [&](int i) {
    return contact::hit_body(scene_.bodies[i], position(y, i), orientation(y, i), velocity(y, i),
                             spin(y, i));
  };
  // Newton's restitution between the surface points, spins and inertia included.
  contact::HitBody a = hit_body(pair.a), b = ground ? contact::HitBody{} : hit_body(pair.b);
  const Vector3d arm_b = p.point - b.position;
  const double closing =
      (a.velocity + a.spin.cross(p.point - a.position) - b.velocity - b.spin.cross(arm_b))
          .dot(p.normal);
  // Touching while separating (a grazing root) needs no impulse.
  if (closing >= 0.0) return;
  check_simultaneous(pair, y, t);
  const bool b_moves = !ground && !scene_.bodies[pair.b].fixed;
  const auto balance = [&](double* energy, Vector3d* angular) {
    State s(scene_.bodies.size());
    read(y, s);
    *energy = 0.0, angular->setZero();
    for (int i : {pair.a, b_moves ? pair.b : -1})
      if (i >= 0)
        *energy += bb::kinetic_energy(scene_.bodies[i], s[i]),
            *angular += bb::angular_momentum(scene_.bodies[i], s[i]);
  };
  double energy_before = 0.0, energy_after = 0.0;
  Vector3d angular_before, angular_after;
  if (b_moves && !trace_.first_collision) balance(&energy_before, &angular_before);
  const Vector3d momentum_before = momentum(y);
  const double j = contact::impulse_hit(a, b, p.point, p.normal, pair.restitution);
  // Coulomb at the impact, for a ball against the ground or a fixed body (exact there).
  if (pair.friction_static > 0.0 || pair.friction_kinetic > 0.0)
    contact::friction_hit(a, b, p.point, p.normal, j, pair.friction_static, pair.friction_kinetic);
  Vec(y + at(pair.a) + 3) = a.velocity;
  set_spin(y, pair.a, a.spin);
  if (b_moves) Vec(y + at(pair.b) + 3) = b.velocity, set_spin(y, pair.b, b.spin);
  record_hit(pair, p.normal, y, t, b_moves);
  if (b_moves && !trace_.first_collision) {
    balance(&energy_after, &angular_after);
    trace_.first_collision = {pair.a,
                              pair.b,
                              t,
                              momentum(y) - momentum_before,
                              angular_after - angular_before,
                              energy_before,
                              energy_after};
  }
  lift_resting(pair, y, t);
  if (!ground) return;
  end_small_bounce(pair, p.gap, y, t);
}

void SceneModel::settle(int i, const double* y, double t) {
  slides_[i] = {};
  if (!resting_[i] || (mu_static_[i] <= 0.0 && mu_kinetic_[i] <= 0.0)) return;
  const Vector3d n = scene_.ground->normal;
  linear_accelerations(y);
  slides_[i] =
      decide_slide(mu_static_[i], n, velocity(y, i), applied_[i], scene_.bodies[i].name, t);
  // A body held from rest has stopped there (at t = 0: at rest from the start).
  if (slides_[i].mode == SlideMode::Stuck) end_motion(i, y, t);
}

void SceneModel::end_motion(int i, const double* y, double t) {
  if (!in_motion_[i]) return;
  in_motion_[i] = false;
  BodyEvents& e = trace_.bodies[i];
  e.stop_time = t, e.stop_position = position(y, i);
}

void SceneModel::stop(int i, double* y, double t) {
  // Located to the event tolerance, the speed along the ground is what that tolerance
  // leaves (about a for 1e-12 s): rest, exactly. A body resting on the ground keeps no speed
  // along its normal either: on a slope, the rounding of v - (v.n) n would otherwise leave
  // a slide of 1e-17 m/s in a direction of its own, across the force.
  const Vector3d n = scene_.ground->normal;
  Vec v(y + at(i) + 3);
  if (resting_[i])
    v.setZero();
  else
    v = v.dot(n) * n;
  end_motion(i, y, t);
  settle(i, y, t);
}

bool SceneModel::lands(int i) const {
  return hinge_[i] != nullptr && scene_.ground && scene_.bodies[i].shape == Shape::Box &&
         ground_pair(scene_, i).has_value();
}

double SceneModel::hinge_alpha(int i, const double* y) {
  linear_accelerations(y);
  const Body& b = scene_.bodies[i];
  const HingeAccelerations a = hinge_accelerations(b, orientation(y, i), position(y, i), spin(y, i),
                                                   b.mass * accelerations_[i], *hinge_[i]);
  return a.angular.dot(hinge_[i]->axis);
}

bool SceneModel::pressed_into_ground(int i, const double* y, double alpha) const {
  const Hinge& h = *hinge_[i];
  const Vector3d& half = scene_.bodies[i].half_extents;
  const Vector3d centre = position(y, i);
  const Quaterniond q = orientation(y, i).normalized();
  const auto height = [&](double turn) {
    const Quaterniond by(Eigen::AngleAxisd(turn, h.axis));
    return contact::clear_height(h.anchor + by * (centre - h.anchor), by * q, half, h.anchor,
                                 h.axis, scene_.ground->point, scene_.ground->normal);
  };
  const double now = height(0.0);
  if (now > kSimultaneousGap) return false;
  // No torque, or a turn that lowers a touching corner: the ground holds the body.
  return alpha == 0.0 || height(alpha > 0.0 ? 1e-6 : -1e-6) < now;
}

void SceneModel::land(const ContactPair& pair, double* y, double t) {
  const int i = pair.a;
  const Vector3d u = hinge_[i]->axis;
  const double omega = Vector3d(spin(y, i)).dot(u);
  // Leaving the ground (a grazing root) needs nothing.
  if (!pressed_into_ground(i, y, omega)) return;
  BodyEvents& e = trace_.bodies[i];
  e.contact_times.push_back(t);
  if (!e.post_velocity)
    e.post_velocity = Vector3d(velocity(y, i)), e.post_normal = scene_.ground->normal;
  // Newton's restitution at the landing corner: about the axis its speed is omega r.
  const double rebound = -pair.restitution * omega;
  set_spin(y, i, rebound * u);
  Vec(y + at(i) + 3) = (rebound * u).cross(Vector3d(position(y, i)) - hinge_[i]->anchor);
  const double alpha = hinge_alpha(i, y);
  const bool short_rebound =
      alpha * rebound < 0.0 && 2.0 * std::abs(rebound / alpha) < rest_flight_time();
  if ((rebound == 0.0 || short_rebound) && pressed_into_ground(i, y, alpha)) {
    hinge_held_[i] = true;
    set_spin(y, i, Vector3d::Zero());
    Vec(y + at(i) + 3).setZero();
  }
}

void SceneModel::apply_impulse(const Impulse& impulse, double t, double* y) {
  const int i = impulse.body;
  Vector3d v = velocity(y, i), w = spin(y, i);
  if (hinge_[i])
    hinge_impulse(scene_.bodies[i], orientation(y, i), position(y, i), impulse.impulse,
                  impulse.point.value_or(Vector3d(position(y, i))), *hinge_[i], v, w);
  else
    contact::apply_impulse(scene_.bodies[i], impulse, position(y, i), orientation(y, i), v, w);
  Vec(y + at(i) + 3) = v;
  set_spin(y, i, w);
  if (!resting_[i]) return;
  // A push that sets a body at rest moving along the ground or off it begins a new motion
  // there: the body's stop is that motion's end (a push at the instant the body came to
  // rest, at t = 0 say, means it did not stop there).
  const Vector3d n = scene_.ground->normal;
  if (!in_motion_[i] && ((v - v.dot(n) * n).norm() > 0.0 || v.dot(n) > 0.0)) {
    BodyEvents& e = trace_.bodies[i];
    in_motion_[i] = true;
    e.motion_start = position(y, i);
    e.stop_time.reset();
  }
  // Along the ground it rests on, the body stays on it and slides (or stays, if the push
  // was nothing along the ground).
  if (v.dot(scene_.ground->normal) == 0.0) return settle(i, y, t);
  resting_[i] = false;
  slides_[i] = {};
  // Pressed into the ground it rests on: the ground answers at once, as at a contact.
  if (v.dot(scene_.ground->normal) < 0.0)
    for (const Source& s : sources_)
      if (s.contact() && s.pair.ground() && s.pair.a == i) resolve(s.pair, y, t);
}

void SceneModel::apply(std::size_t k, double t, double* y) {
  const Source& s = sources_[k];
  // A crossing applied with another event at the same instant may show up again just after
  // it, when its velocity was still a hair below zero: it is one crossing.
  switch (s.watch) {
    case Watch::HingeSwing: {
      std::vector<double>& crossings = trace_.bodies[s.body].hinge_crossings;
      if (crossings.empty() || t - crossings.back() > 1e-9) crossings.push_back(t);
      return;
    }
    case Watch::Swing: {
      std::vector<Turn>& turns = trace_.bodies[s.body].turns[s.axis];
      const bool lowest = !s.down;
      if (turns.empty() || turns.back().lowest != lowest || t - turns.back().time > 1e-9)
        turns.push_back({t, position(y, s.body)[s.axis], lowest});
      return;
    }
    case Watch::Stop:
      return stop(s.body, y, t);
    case Watch::Fall: {
      std::optional<double>& fell = trace_.bodies[s.body].fall_time;
      if (!fell) fell = t;
      return;
    }
    case Watch::Crossing: {
      std::vector<Crossing>& crossings = trace_.crossings[s.observe.name];
      const bool rising = !s.down;
      if (crossings.empty() || crossings.back().rising != rising ||
          t - crossings.back().time > 1e-9)
        crossings.push_back({t, rising});
      return;
    }
    case Watch::Apex: {
      const Vector3d above = Vector3d(position(y, s.body)) - scene_.ground->point;
      trace_.bodies[s.body].apex_heights.push_back(above.dot(scene_.ground->normal));
      after_bounce_[s.body] = false;
      return;
    }
    case Watch::Contact:
      if (s.pair.ground() && lands(s.pair.a)) return land(s.pair, y, t);
      return resolve(s.pair, y, t);
  }
}

}  // namespace bb
