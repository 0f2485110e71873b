// Hinges in Box2D as its users build them: one b2RevoluteJoint per [[hinge]] between a
// static ground body at the origin and the body, at the anchor, with no limit and no motor.
#pragma once

#include <box2d/box2d.h>

#include <vector>

#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// Builds the scene's hinges in `world` (which owns the joints and the ground body).
void make_box2d_hinges(const World& scene, b2World& world, const std::vector<b2Body*>& bodies);

/// How make_box2d_hinges builds them, for engine_settings.
void add_box2d_hinge_settings(Settings& out);

}  // namespace bb
