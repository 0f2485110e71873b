// The scene's equations of motion for free bodies: gravity plus air forces, per body.
// The course methods and the reference integrate these same equations; they differ only
// in how they step through time.
#pragma once

#include <vector>

#include "scene/scene.hpp"
#include "scene/state.hpp"

namespace bb {

/// Linear acceleration (m/s^2) of every body at positions `x` and velocities `v`;
/// `omega` is each body's angular velocity. Fixed bodies get zero.
void accelerations(const Scene& scene, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                   const std::vector<Vec3>& omega, std::vector<Vec3>& out);

/// Total mechanical energy (J): kinetic, rotational and gravitational (zero at the origin).
double total_energy(const Scene& scene, const State& state);

/// The state the case file describes at t = 0.
State initial_state(const Scene& scene);

}  // namespace bb
