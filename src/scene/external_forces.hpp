// The forces the harness adds to an engine's bodies before each of its steps, computed
// from the engine's own current state, the way a game adds them: air drag, wind, the
// Magnus force, the wind on a panel (a box's broad face), and springs applied by hand. Every
// adapter calls this one function instead of keeping its own copy of the loop.
#pragma once

#include <vector>

#include "scene/scene.hpp"
#include "scene/spring_forces.hpp"
#include "scene/state.hpp"

namespace bb {

/// Whether the scene has any force for the adapters to add (else they skip reading state).
bool has_external_forces(const Scene& scene);

/// The force (N, at the centre of mass) on each body at `state`; zero on fixed bodies.
/// `forces` is resized to the number of bodies; nothing is allocated once it has that size.
/// `springs_by_hand`, when given, adds the scene's springs too (the `<engine>/force`
/// backends, which build no engine joint for them).
void external_forces(const Scene& scene, const State& state, std::vector<Vec3>& forces,
                     const SpringNetwork* springs_by_hand = nullptr);

}  // namespace bb
