// How each of Bullet's backends starts its runs, for the plugins' entry points
// (bullet_plugin.cpp, bullet_float_plugin.cpp).
#pragma once

#include "../described_backend.hpp"

namespace bb {

/// Bullet's rigid bodies, the springs as `springs` (bullet_backend.cpp).
DeclaredBackend::Start bullet_rigid_start(SpringsAs springs);

/// The spring scenes as one soft body (bullet_softbody_backend.cpp).
DeclaredBackend::Start bullet_softbody_start();

}  // namespace bb
