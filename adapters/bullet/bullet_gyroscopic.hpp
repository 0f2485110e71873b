// Bullet's gyroscopic term, set on every moving body from the case's gyroscopic_term key
// and recorded. Bullet 3.24's btRigidBody constructor already sets
// BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY (btRigidBody.cpp, setupRigidBody); the adapter
// sets it, or clears it, so that a change of default cannot pass unnoticed.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <string>

#include "bullet_engine.hpp"
#include "model/world.hpp"
#include "seam/backend.hpp"
#include "seam/engine_keys.hpp"
#include "seam/engine_tables.hpp"

namespace bb {

/// The three gyroscopic flags of btRigidBodyFlags; a body carries at most the one chosen.
inline constexpr int kBulletGyroscopicFlags = BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT |
                                              BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD |
                                              BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;

/// Whether the case keeps the gyroscopic term (the key gyroscopic_term, on by default).
inline bool bullet_gyroscopic(const EngineTables& engines) {
  return engine_setting(engines, bullet_description(), "gyroscopic_term") != 0.0;
}

/// Sets `body`'s gyroscopic flag from the case, leaving its other flags as they are.
inline void set_bullet_gyroscopic(const EngineTables& engines, btRigidBody& body) {
  const int chosen = bullet_gyroscopic(engines) ? BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY : 0;
  body.setFlags((body.getFlags() & ~kBulletGyroscopicFlags) | chosen);
}

/// Appends "gyroscopic": the flag set on every moving body and what it does.
inline void add_bullet_gyroscopic_setting(const EngineTables& engines, Settings& settings) {
  settings.push_back(
      {"gyroscopic",
       bullet_gyroscopic(engines)
           ? std::string(
                 "BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY on every moving body (Bullet's "
                 "default, set explicitly; EXPLICIT and IMPLICIT_WORLD off): before the solve, "
                 "one Newton step of implicit Euler on Euler's equations in the body frame, "
                 "I w' + h w' x I w' = I w (computeGyroscopicImpulseImplicit_Body), added to "
                 "the spin as an impulse; stable, it keeps the flip but takes energy and |L| "
                 "together (|L|^2 / 2E stays put): spinning_box at 1/60 s flips as often as "
                 "the reference while losing 40% of its energy and 22% of |L| in 10 s")
           : std::string("off (gyroscopic_term = false: no BT_ENABLE_GYROSCOPIC_FORCE_* flag): "
                         "nothing turns the spin, a free body keeps its world angular velocity "
                         "and never flips")});
}

}  // namespace bb
