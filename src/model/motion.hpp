// Quantities of a body's motion the harness reads from any backend's state: energy,
// angular momentum, and the state a case starts in. (The forces: physics/force_model.hpp;
// the total energy, which adds each force term's potential: physics/energy.hpp.)
#pragma once

#include "model/state.hpp"
#include "model/world.hpp"

namespace bb {

/// Kinetic energy (J) of one body, its spin's part included; zero for a fixed body.
double kinetic_energy(const Body& body, const BodyState& state);

/// Angular momentum (N m s) of one body about the world's origin: r x m v + J omega.
Vec3 angular_momentum(const Body& body, const BodyState& state);

/// The state the case file describes at t = 0.
State initial_state(const World& scene);

}  // namespace bb
