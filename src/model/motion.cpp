#include "model/motion.hpp"

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
