#include "physics/state_forces.hpp"

namespace bb {

StateForces::StateForces(const World& scene, const ForceOptions& options)
    : model_(scene, options),
      x_(scene.bodies.size()),
      v_(scene.bodies.size()),
      w_(scene.bodies.size()),
      q_(scene.bodies.size()),
      loads_(model_.make_loads()) {}

const Loads& StateForces::at(const State& state) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    x_[i] = state[i].position, v_[i] = state[i].velocity;
    q_[i] = state[i].orientation, w_[i] = state[i].angular_velocity;
  }
  model_.evaluate({x_.data(), v_.data(), q_.data(), w_.data()}, loads_);
  return loads_;
}

}  // namespace bb
