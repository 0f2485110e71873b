// The reference of a [waves] case: the Gerstner formula itself (seed section 10), evaluated
// at each step's time. A kinematic surface has nothing to integrate, so its truth is the
// formula, exactly.
#pragma once

#include <memory>

#include "seam/backend.hpp"

namespace bb {

/// A run of `world`'s wave surface at steps of `dt`; `world.waves` must be set.
std::unique_ptr<Simulation> start_wave_surface(const World& world, double dt);

}  // namespace bb
