// The scene's total mechanical energy, read from any backend's state: kinetic (spin
// included), gravity's potential, and every force term's own potential energy
// (force_term.hpp), so that a new term with a potential is counted without an edit here.
#pragma once

#include "physics/state_forces.hpp"

namespace bb {

/// Reads the total energy of states of one scene; built once per run (it holds the force
/// model), it allocates nothing per read.
class EnergyMeter {
 public:
  explicit EnergyMeter(const World& scene);
  /// Total mechanical energy (J) at `state`: kinetic, gravitational (zero at the origin) and
  /// the force terms' potential energy.
  double operator()(const State& state);
  const ForceModel& model() const { return forces_.model(); }

 private:
  const World& scene_;
  StateForces forces_;
};

/// The same for one state, building the force model anew: for a single read.
double total_energy(const World& scene, const State& state);

}  // namespace bb
