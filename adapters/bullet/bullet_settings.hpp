// Bullet's solver settings from the case's [engines.bullet] keys, and the description of
// its contact handling that every run with contacts writes into engine_settings.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

#include "bullet_contacts.hpp"
#include "model/world.hpp"
#include "seam/backend.hpp"
#include "seam/engine_tables.hpp"

namespace bb {

/// How the adapter applies an [[impulse]], for engine_settings.
inline constexpr const char* kImpulseMethod =
    "btRigidBody::applyImpulse(J, point - centre of mass) after activate(), before the step "
    "that starts at its time";

/// Sets every solver parameter that changes contacts, from the keys or explicitly.
void configure_solver(const EngineTables& engines, btContactSolverInfo& info);

/// What the scene's collision shapes carry, one entry per shape, metres.
struct ShapeFigures {
  std::vector<double> margins;
  /// Each shape's contact breaking threshold: a pair uses the smaller of its two.
  std::vector<double> breaking_thresholds;
};

/// Appends the contact and friction rules and the values in effect.
void add_contact_settings(const World& scene, const EngineTables& engines,
                          const btContactSolverInfo& info, const ShapeFigures& shapes,
                          const PlaneMultipoint& multipoint, Settings& out);

}  // namespace bb
