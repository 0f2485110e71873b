// The MJCF model of a World for MuJoCo, written in memory: per moving body a free joint in
// 3D, or two slide joints (x, y) and a hinge (z) in 2D, its mass and principal inertia; a
// fixed body welded to the world. No geoms: nothing touches (contacts are not built yet).
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace bb {

/// The model's XML at step `dt`.
std::string mujoco_model_xml(const World& world, double dt);

}  // namespace bb
