// The per-step observer's contacts: each watched pair's episodes of approach and contact,
// and the balance of momentum, angular momentum and energy over the first collision between
// two moving bodies.
#include <algorithm>
#include <cmath>

#include "model/motion.hpp"
#include "observe/step_observer.hpp"

namespace bb {

namespace {
double radius(const Body& b) {
  return b.shape == Shape::Sphere ? b.radius : 0.0;
}

/// Kinetic energy (J, spins included) of bodies a and b.
double kinetic_energy(const Scene& scene, const State& s, int a, int b) {
  return bb::kinetic_energy(scene.bodies[a], s[a]) + bb::kinetic_energy(scene.bodies[b], s[b]);
}

/// Momentum (N s) of bodies a and b.
Vec3 momentum(const Scene& scene, const State& s, int a, int b) {
  return s[a].velocity * scene.bodies[a].mass + s[b].velocity * scene.bodies[b].mass;
}

/// Angular momentum (N m s) of bodies a and b about the origin.
Vec3 angular_momentum(const Scene& scene, const State& s, int a, int b) {
  return bb::angular_momentum(scene.bodies[a], s[a]) + bb::angular_momentum(scene.bodies[b], s[b]);
}

}  // namespace

void StepObserver::write_episode(std::size_t k, double t, const State& s) {
  const ContactPair& pair = pairs_[k];
  const Episode& ep = episodes_[k];
  for (int body : {pair.a, pair.b}) {
    if (body < 0 || post_owner_[body] != static_cast<int>(k)) continue;
    trace_.bodies[body].post_velocity = s[body].velocity;
  }
  if (!ep.balances) return;
  // The two bodies' balance over the episode, less what gravity did meanwhile: its impulse
  // m g (t - t0), its work m g . dx and its angular impulse. The rest is the collision's.
  const Body &body_a = scene_.bodies[pair.a], &body_b = scene_.bodies[pair.b];
  const double mass = body_a.mass + body_b.mass;
  const BodyState &a0 = ep.a0, &b0 = ep.b0;
  const double gravity_work = scene_.gravity.dot((s[pair.a].position - a0.position) * body_a.mass +
                                                 (s[pair.b].position - b0.position) * body_b.mass);
  const Vec3 momentum_before = a0.velocity * body_a.mass + b0.velocity * body_b.mass;
  const Vec3 angular_before = bb::angular_momentum(body_a, a0) + bb::angular_momentum(body_b, b0);
  const double energy_before = bb::kinetic_energy(body_a, a0) + bb::kinetic_energy(body_b, b0);
  trace_.first_collision = {
      pair.a,
      pair.b,
      ep.event_time,
      momentum(scene_, s, pair.a, pair.b) - momentum_before -
          scene_.gravity * (mass * (t - ep.start_time)),
      angular_momentum(scene_, s, pair.a, pair.b) - angular_before - ep.gravity_turn,
      energy_before,
      kinetic_energy(scene_, s, pair.a, pair.b) - gravity_work};
}

bool StepObserver::episode_watched(const ContactPair& pair) const {
  // Until each body's first contact is read and, for two moving bodies, the first collision.
  for (int body : {pair.a, pair.b})
    if (body >= 0 && (!trace_.bodies[body].post_velocity || post_owner_[body] >= 0)) return true;
  return !pair.ground() && !scene_.bodies[pair.b].fixed &&
         (!trace_.first_collision || balance_open_);
}

void StepObserver::observe_contacts(double t, double dt, const State& s) {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& pair = pairs_[k];
    const int b = pair.ground() ? pair.a : pair.b;
    const contact::Proximity p =
        contact::measure(scene_, pair, s[pair.a].position, s[b].position, s[b].orientation);
    const bool b_moves = !pair.ground() && !scene_.bodies[pair.b].fixed;
    const Eigen::Vector3d relative =
        s[pair.a].velocity - (b_moves ? s[pair.b].velocity : Eigen::Vector3d::Zero());
    const double closing = -relative.dot(p.normal);
    if (p.gap < 0.0) {
      BodyEvents& a = trace_.bodies[pair.a];
      a.max_penetration = std::max(a.max_penetration, -p.gap);
      if (b_moves)
        trace_.bodies[pair.b].max_penetration =
            std::max(trace_.bodies[pair.b].max_penetration, -p.gap);
    }
    // A contact: close, approaching at the last step, no longer approaching at this one.
    // "Close" allows for the distance the approach covers in two steps: a bounce may turn
    // a body around before it reaches the surface.
    const double near = 2.0 * std::max(closing_[k], 0.0) * dt + 0.1 * radius(scene_.bodies[pair.a]);
    // Along the last step's normal, so a body that passed through a thin panel (whose
    // normal flips as the centre crosses it) is not mistaken for one that bounced.
    const double closing_before_normal = -relative.dot(normals_[k]);
    // Stopped approaching, up to single precision's rounding: a plastic collision in a
    // float engine leaves the two bodies a few ulps apart in speed.
    const double rounding =
        1e-5 * (s[pair.a].velocity.norm() + (b_moves ? s[pair.b].velocity.norm() : 0.0));
    const bool hit =
        !first_ && closing_[k] > rounding && closing_before_normal <= rounding && p.gap < near;
    // Pushed apart over the step: a hit, or close and the speed of approach along a fixed
    // normal fell by more than rounding (gravity and the flight only keep it or raise it).
    const bool pushed =
        hit || (!first_ && p.gap < near && closing_[k] - closing_before_normal > rounding);
    Episode& ep = episodes_[k];
    // Pushed without a hit, outside a contact that began with one: while overlapping, or
    // hard (a tenth of the approach gone in one step), not as a force across the gap eases
    // an approach; and from an approach faster than gravity gives in a step, not a body
    // resting on another, which its contact holds there against gravity.
    const bool hard = closing_[k] - closing_before_normal > kHardPush * closing_[k];
    const bool approaching = closing_[k] > scene_.gravity.norm() * dt;
    if (!first_ && pushed && !hit && !ep.open && approaching && (p.gap < 0.0 || hard))
      note_unresolved(k, t, closing);
    if (!first_ && episode_watched(pair)) {
      if (ep.open && pushed && !hit) {
        // A contact that lasts (a soft one) is read at the last step that still pushes; a
        // new hit is a new contact.
        if (b_moves) ep.gravity_turn += gravity_turn(s, pair.a, pair.b, dt);
        write_episode(k, t, s);
      } else if (ep.open) {
        close_episode(k);
      }
      if (!pushed) {
        ep.start_time = t, ep.a0 = s[pair.a], ep.b0 = s[b];
        ep.gravity_turn = Vec3::Zero();
      } else if (!ep.open && b_moves) {
        ep.gravity_turn += gravity_turn(s, pair.a, pair.b, dt);
      }
    }
    if (hit) record_hit(k, t, s, p.normal, b_moves);
    closing_[k] = closing;
    normals_[k] = p.normal;
  }
}

void StepObserver::record_hit(std::size_t k, double t, const State& s,
                              const Eigen::Vector3d& normal, bool b_moves) {
  const ContactPair& pair = pairs_[k];
  Episode& ep = episodes_[k];
  for (int body : {pair.a, b_moves ? pair.b : -1}) {
    if (body < 0) continue;
    BodyEvents& e = trace_.bodies[body];
    e.contact_times.push_back(t);
    // The normal points from the second shape to the first: away from b for a.
    if (!e.post_velocity) {
      e.post_normal = body == pair.a ? Vec3(normal) : Vec3(-normal);
      post_owner_[body] = static_cast<int>(k);
    }
    bounced_[body] = true;
  }
  if (b_moves && !trace_.first_collision) ep.balances = balance_open_ = true;
  if (!ep.open) {
    ep.open = true;
    ep.event_time = t;
  }
  write_episode(k, t, s);
}

void StepObserver::note_unresolved(std::size_t k, double t, double closing) {
  const ContactPair& pair = pairs_[k];
  const bool b_moves = !pair.ground() && !scene_.bodies[pair.b].fixed;
  for (int body : {pair.a, b_moves ? pair.b : -1}) {
    if (body < 0) continue;
    const int other = body == pair.a ? (pair.ground() ? -1 : pair.b) : pair.a;
    const bool other_moves = other >= 0 && !scene_.bodies[other].fixed;
    std::optional<UnresolvedContact>& u = trace_.bodies[body].unresolved_contact;
    const bool by_moving = u && u->other >= 0 && !scene_.bodies[u->other].fixed;
    // The first such push of the body; one with a moving body before one with the ground.
    if (!u || (other_moves && !by_moving))
      u = UnresolvedContact{other, t, closing_[k], closing};
    else if (u->other == other)
      u->approach_least = std::min(u->approach_least, closing);
  }
}

void StepObserver::close_episode(std::size_t k) {
  Episode& ep = episodes_[k];
  for (int& owner : post_owner_)
    if (owner == static_cast<int>(k)) owner = -1;
  if (ep.balances) balance_open_ = false;
  ep.open = ep.balances = false;
}

Vec3 StepObserver::gravity_turn(const State& s, int a, int b, double dt) const {
  // Gravity's angular impulse about the origin over the step, at the mid positions.
  Vec3 turn = Vec3::Zero();
  for (int i : {a, b})
    turn += (0.5 * (s[i].position + previous_[i].position))
                .cross(scene_.gravity * (scene_.bodies[i].mass * dt));
  return turn;
}

}  // namespace bb
