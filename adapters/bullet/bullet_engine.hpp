// Bullet as the harness knows it: one settings table, four backends (double and single
// precision builds of the same adapter with springs as Bullet's constraints, the double
// build with springs applied by hand, and a soft body of the spring scenes), and its keys
// with their defaults.
#pragma once

#include "seam/engine_catalogue.hpp"

namespace bb {

/// Every feature: the rigid-body builds.
inline FeatureSet bullet_rigid_supports() {
  return force_stage_features() | FeatureSet{Feature::ThreeD,      Feature::Rotation,
                                             Feature::Boxes,       Feature::GroundContact,
                                             Feature::BodyContact, Feature::Restitution,
                                             Feature::Impulse,     Feature::Springs,
                                             Feature::Friction,    Feature::Hinge};
}

inline EngineDescription bullet_engine() {
  const std::string e = "bullet";
  return {
      .engine = e,
      .variants = {{.name = "bullet", .colour = "#9367bd", .supports = bullet_rigid_supports()},
                   // Bullet's single-precision libraries, whose symbols are the double ones'
                   // names: a plugin of its own, loaded apart (RTLD_LOCAL).
                   {.name = "bullet-float",
                    .colour = "#e476c2",
                    .supports = bullet_rigid_supports(),
                    .single_precision = true,
                    .plugin = "bullet-float"},
                   {.name = "bullet/force",
                    .colour = "#8a564b",
                    .supports = bullet_rigid_supports(),
                    .needs = {Feature::Springs}},
                   // One soft body of point masses and springs: no shapes, no contacts, no air.
                   {.name = "bullet-softbody",
                    .colour = "#c39b93",
                    .supports = {Feature::ThreeD, Feature::Gravity, Feature::Springs,
                                 Feature::Impulse},
                    .needs = {Feature::Springs}}},
      .keys = {{e, "solver_iterations", KeyKind::Integer, 10, "sequential-impulse iterations"},
               {e, "erp", KeyKind::Number, 0.2, "error reduction per step, joints (m_erp)"},
               {e, "contact_erp", KeyKind::Number, 0.2,
                "error reduction per step of contact penetration (m_erp2)"},
               {e, "split_impulse", KeyKind::Boolean, 1, "split-impulse position correction"},
               {e, "split_impulse_depth", KeyKind::Number, 0.04,
                "m; deeper penetrations are split off (m_splitImpulsePenetrationThreshold = "
                "-depth), shallower ones push in the velocity"},
               {e, "restitution_velocity_threshold", KeyKind::Number, 0.2,
                "m/s; slower normal approach bounces with no restitution"},
               {e, "warm_starting", KeyKind::Boolean, 1,
                "start contacts from 0.85 of last step's impulse (SOLVER_USE_WARMSTARTING)"},
               {e, "ccd", KeyKind::Boolean, 0,
                "continuous collision detection: swept sphere, motion threshold the inner radius"},
               {e, "linear_damping", KeyKind::Number, 0.0, "built-in linear damping, 1/s"},
               {e, "angular_damping", KeyKind::Number, 0.0, "built-in angular damping, 1/s"},
               {e, "gyroscopic_term", KeyKind::Boolean, 1,
                "the gyroscopic term w x I w: BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY on every "
                "moving rigid body (Bullet's default); false clears it"},
               {e, "spring_limit_if_needed", KeyKind::Boolean, 1,
                "btGeneric6DofSpring2Constraint's limitIfNeeded: stiffness and damping cut to "
                "what the step can hold (Bullet's default)"}},
      .names_in_settings = {{"gyroscopic",
                             "BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY on every moving body"},
                            {"hinge", "btHingeConstraint"},
                            {"plane_2d", "setLinearFactor(1, 1, 0)"}},
      .hinge_numbers = {"hinge_erp", "hinge_cfm"}};
}

/// The description, made once: what the adapter reads its settings' defaults from.
inline const EngineDescription& bullet_description() {
  static const EngineDescription description = bullet_engine();
  return description;
}

}  // namespace bb
