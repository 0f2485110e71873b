// Hinges in ODE as its users build them: one hinge joint (dJointCreateHinge) per [[hinge]]
// between the body and the static environment (body 0), at the anchor about the axis.
#pragma once

#include <ode/ode.h>

#include <vector>

#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// Builds the scene's hinges in `world` (which owns and destroys the joints).
void make_ode_hinges(const World& scene, dWorldID world, const std::vector<dBodyID>& bodies);

/// How make_ode_hinges builds them, for engine_settings.
void add_ode_hinge_settings(dWorldID world, Settings& out);

}  // namespace bb
