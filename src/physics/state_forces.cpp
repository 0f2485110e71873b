#include "physics/state_forces.hpp"

namespace bb {

StateForces::StateForces(const World& scene, const ForceOptions& options)
    : model_(scene, options),
      x_(scene.bodies.size()),
      v_(scene.bodies.size()),
      w_(scene.bodies.size()),
      q_(scene.bodies.size()),
      loads_(model_.make_loads()) {}

BodyStates StateForces::view(const State& state) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    x_[i] = state[i].position, v_[i] = state[i].velocity;
    q_[i] = state[i].orientation, w_[i] = state[i].angular_velocity;
  }
  return {x_.data(), v_.data(), q_.data(), w_.data()};
}

const Loads& StateForces::at(const State& state) {
  model_.evaluate(view(state), loads_);
  return loads_;
}

}  // namespace bb
