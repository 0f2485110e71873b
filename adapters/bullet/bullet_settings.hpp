// Bullet's solver settings from the case's [engines.bullet] keys, and the description of
// its contact handling that every run with contacts writes into engine_settings.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <utility>

#include "scene/backend.hpp"
#include "scene/scene.hpp"

namespace bb {

/// How the adapter applies an [[impulse]], for engine_settings.
inline constexpr const char* kImpulseMethod =
    "btRigidBody::applyImpulse(J, point - centre of mass) after activate(), before the step "
    "that starts at its time";

/// Sets every solver parameter that changes contacts, from the keys or explicitly.
void configure_solver(const Scene& scene, btContactSolverInfo& info);

/// Appends the contact rules and the values in effect; `margins` is the smallest and largest
/// collision margin of the scene's shapes, metres.
void add_contact_settings(const Scene& scene, const btContactSolverInfo& info,
                          std::pair<double, double> margins, Settings& out);

}  // namespace bb
