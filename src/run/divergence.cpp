#include "run/divergence.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bb {

namespace {

/// Whether a body of `scene` feels a constant force: its own, or the wind's on a wall.
bool pushed(const Scene& scene) {
  if (scene.features().has(Feature::AppliedForce)) return true;
  for (const Body& b : scene.bodies)
    if (b.wind_force.norm() > 0.0) return true;
  return false;
}

}  // namespace

DivergenceBounds divergence_bounds(const Scene& scene) {
  // Fastest plausible speed: the largest over the bodies of the speed it starts with and
  // gets from its impulses (J / m each) and its constant forces, the wind's on a wall among them
  // (F t / m), and a sail's drive (at most ten times the wind: an ice boat reaches about five),
  // plus the speed its spin
  // gives its surface (its initial spin and the impulses' angular impulses over its smallest
  // moment, times its reach); plus the wind, plus what gravity adds over the whole run. A spin's
  // energy is within 1/2 m (w reach)^2, since no moment exceeds m reach^2.
  double speed = 0.0, size = 1.0, mass = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    // How far its surface (or, on a hinge, its centre) is from where it turns about.
    double reach = b.radius + b.half_extents.norm();
    for (const Hinge& h : scene.hinges)
      if (h.body == static_cast<int>(i)) reach += (b.position - h.anchor).norm();
    const double moment = principal_inertia(b).minCoeff();
    double v = b.velocity.norm(), w = b.angular_velocity.norm();
    // A constant force and torque add to the speed and the spin over the whole run.
    if (!b.fixed) v += (b.force.norm() + b.wind_force.norm()) / b.mass * scene.duration;
    if (b.sail && scene.air) v += 10.0 * scene.air->wind.norm();
    if (moment > 0.0) w += b.torque.norm() / moment * scene.duration;
    for (const Impulse& imp : scene.impulses) {
      if (imp.body != static_cast<int>(i)) continue;
      v += imp.impulse.norm() / b.mass;
      const double arm = (imp.point.value_or(b.position) - b.position).norm() + reach;
      if (moment > 0.0) w += arm * imp.impulse.norm() / moment;
    }
    speed = std::max(speed, v + w * reach);
    size = std::max(size, b.position.norm() + b.radius + b.half_extents.norm());
    mass += b.mass;
  }
  const double t = scene.duration, g = scene.gravity.norm();
  if (scene.air) speed += scene.air->wind.norm();
  speed += g * t;
  // Springs stretched at the start give their energy to the lightest body at most.
  double spring_energy = 0.0, lightest = 0.0;
  for (const Spring& s : scene.springs) {
    const double stretch =
        (scene.bodies[s.body_b].position - scene.bodies[s.body_a].position).norm() - s.rest_length;
    spring_energy += 0.5 * s.stiffness * stretch * stretch;
  }
  for (const Body& b : scene.bodies)
    if (!b.fixed && (lightest == 0.0 || b.mass < lightest)) lightest = b.mass;
  if (lightest > 0.0) speed += std::sqrt(2.0 * spring_energy / lightest);
  const double travel = speed * t + size;
  DivergenceBounds bounds;
  bounds.travel = 10.0 * travel;
  bounds.energy_scale = 0.5 * mass * speed * speed + mass * g * travel + spring_energy + 1.0;
  // Far above a bounded swing (semi-implicit Euler near its limit swings its energy by a
  // factor of 100 and is stable), low enough to stop an exponential blow-up early.
  bounds.energy = 1e4 * bounds.energy_scale;
  return bounds;
}

std::optional<std::string> divergence(const Scene& scene, const DivergenceBounds& bounds,
                                      const State& state, double initial_energy, double energy) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    const BodyState& s = state[i];
    const std::string& name = scene.bodies[i].name;
    if (!s.position.allFinite() || !s.velocity.allFinite() || !s.angular_velocity.allFinite())
      return "body '" + name + "' has a NaN or infinite position or velocity";
    if ((s.position - scene.bodies[i].position).norm() > bounds.travel) {
      std::ostringstream m;
      m << "body '" << name << "' moved more than " << bounds.travel
        << " m from its start, ten times what gravity, the initial speeds and spins"
        << (pushed(scene) ? ", the impulses and the constant forces" : " and the impulses")
        << " allow";
      return m.str();
    }
  }
  const double change = std::abs(energy - initial_energy);
  if (change > bounds.energy) {
    std::ostringstream m;
    m << "energy changed by " << change << " J, more than the bound of " << bounds.energy
      << " J derived from the scene";
    return m.str();
  }
  return std::nullopt;
}

}  // namespace bb
