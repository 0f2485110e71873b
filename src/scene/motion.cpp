#include "scene/motion.hpp"

#include "scene/air_forces.hpp"

namespace bb {

void accelerations(const Scene& scene, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                   const std::vector<Vec3>& omega, std::vector<Vec3>& out) {
  (void)x;  // no position-dependent force yet (springs and contacts add them)
  out.resize(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (body.fixed) {
      out[i] = {};
      continue;
    }
    out[i] = scene.gravity + air_force(scene, body, v[i], omega[i]) / body.mass;
  }
}

double total_energy(const Scene& scene, const State& state) {
  double energy = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (body.fixed) continue;
    const BodyState& s = state[i];
    const Vec3 inertia = principal_inertia(body);
    // Rotational energy uses the spin in the body's own frame, where the inertia is diagonal.
    const Vec3 w = rotate(s.orientation.conjugate(), s.angular_velocity);
    const double rotational = 0.5 * (inertia.x() * w.x() * w.x() + inertia.y() * w.y() * w.y() +
                                     inertia.z() * w.z() * w.z());
    energy += 0.5 * body.mass * s.velocity.dot(s.velocity) + rotational -
              body.mass * scene.gravity.dot(s.position);
  }
  return energy;
}

State initial_state(const Scene& scene) {
  State state(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    state[i] = {b.position, b.fixed ? Vec3{} : b.velocity, b.orientation,
                b.fixed ? Vec3{} : b.angular_velocity};
  }
  return state;
}

}  // namespace bb
