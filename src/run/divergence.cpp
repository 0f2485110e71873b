#include "run/divergence.hpp"

#include <cmath>
#include <sstream>

namespace bb {

DivergenceBounds divergence_bounds(const Scene& scene) {
  // Fastest plausible speed: the largest initial speed, plus the wind, plus what gravity
  // adds over the whole run; the farthest travel follows from it.
  double speed = 0.0, size = 1.0, mass = 0.0;
  for (const Body& b : scene.bodies) {
    speed = std::max(speed, b.velocity.norm() + b.angular_velocity.norm() * b.radius);
    size = std::max(size, b.position.norm() + b.radius + b.half_extents.norm());
    mass += b.mass;
  }
  const double t = scene.duration, g = scene.gravity.norm();
  if (scene.air) speed += scene.air->wind.norm();
  speed += g * t;
  const double travel = speed * t + size;
  DivergenceBounds bounds;
  bounds.travel = 10.0 * travel;
  bounds.energy_scale = 0.5 * mass * speed * speed + mass * g * travel + 1.0;
  bounds.energy = 10.0 * bounds.energy_scale;
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
        << " m from its start, ten times what gravity and the initial speeds allow";
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
