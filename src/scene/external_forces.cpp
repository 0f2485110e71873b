#include "scene/external_forces.hpp"

#include "scene/air_forces.hpp"

namespace bb {

bool has_external_forces(const Scene& scene) {
  for (const Body& b : scene.bodies)
    if (!b.wind_force.isZero()) return true;
  return scene.air.has_value();
}

void external_forces(const Scene& scene, const State& state, std::vector<Vec3>& forces,
                     const SpringNetwork* springs_by_hand) {
  forces.resize(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    forces[i] = b.fixed ? Vec3{}
                        : Vec3(air_force(scene, b, state[i].velocity, state[i].angular_velocity) +
                               panel_wind_force(b, state[i].orientation));
  }
  if (springs_by_hand == nullptr) return;
  add_spring_forces(*springs_by_hand, state, forces.data());
  // A fixed body is an anchor: its end of a spring pulls on nothing that moves.
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].fixed) forces[i].setZero();
}

}  // namespace bb
