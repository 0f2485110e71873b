#include "scene/motion.hpp"

namespace bb {

double kinetic_energy(const Body& body, const BodyState& s) {
  if (body.fixed) return 0.0;
  const Vec3 inertia = principal_inertia(body);
  // Rotational energy uses the spin in the body's own frame, where the inertia is diagonal.
  const Vec3 w = rotate(s.orientation.conjugate(), s.angular_velocity);
  const double rotational = 0.5 * (inertia.x() * w.x() * w.x() + inertia.y() * w.y() * w.y() +
                                   inertia.z() * w.z() * w.z());
  return 0.5 * body.mass * s.velocity.dot(s.velocity) + rotational;
}

Vec3 angular_momentum(const Body& body, const BodyState& s) {
  if (body.fixed) return Vec3::Zero();
  const Vec3 w = rotate(s.orientation.conjugate(), s.angular_velocity);
  const Vec3 spin = rotate(s.orientation, Vec3(principal_inertia(body).cwiseProduct(w)));
  return s.position.cross(body.mass * s.velocity) + spin;
}

double total_energy(const World& scene, const State& state) {
  double energy = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (body.fixed) continue;
    const BodyState& s = state[i];
    energy += kinetic_energy(body, s) - body.mass * scene.gravity.dot(s.position);
  }
  for (const Spring& spring : scene.springs) {
    const double stretch =
        (state[spring.body_b].position - state[spring.body_a].position).norm() - spring.rest_length;
    energy += 0.5 * spring.stiffness * stretch * stretch;
  }
  return energy;
}

State initial_state(const World& scene) {
  State state(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    state[i] = {b.position, b.fixed ? Vec3{} : b.velocity, b.orientation,
                b.fixed ? Vec3{} : b.angular_velocity};
  }
  return state;
}

}  // namespace bb
