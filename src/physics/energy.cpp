#include "physics/energy.hpp"

#include "model/motion.hpp"

namespace bb {

EnergyMeter::EnergyMeter(const World& scene) : scene_(scene), forces_(scene) {}

double EnergyMeter::operator()(const State& state) {
  double energy = 0.0;
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
    const Body& body = scene_.bodies[i];
    if (body.fixed) continue;
    energy += kinetic_energy(body, state[i]) - body.mass * scene_.gravity.dot(state[i].position);
  }
  if (forces_.model().stores_energy())
    energy += forces_.model().potential_energy(forces_.view(state));
  return energy;
}

double total_energy(const World& scene, const State& state) {
  return EnergyMeter(scene)(state);
}

}  // namespace bb
