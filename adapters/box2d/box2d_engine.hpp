// Box2D as the harness knows it: `box2d` (springs as distance joints) and `box2d/force`
// (springs added by hand, on spring scenes only), its settings keys and their defaults.
#pragma once

#include "seam/engine_catalogue.hpp"

namespace bb {

/// Everything but 3D: Box2D is a 2D engine.
inline FeatureSet box2d_supports() {
  return force_stage_features() |
         FeatureSet{Feature::Rotation,    Feature::Boxes,       Feature::GroundContact,
                    Feature::BodyContact, Feature::Restitution, Feature::Impulse,
                    Feature::Springs,     Feature::Friction,    Feature::Hinge};
}

inline EngineDescription box2d_engine() {
  const std::string e = "box2d";
  return {
      .engine = e,
      // Box2D computes in float.
      .variants = {{.name = "box2d",
                    .colour = "#00c0cf",
                    .supports = box2d_supports(),
                    .single_precision = true},
                   {.name = "box2d/force",
                    .colour = "#006d79",
                    .supports = box2d_supports(),
                    .needs = {Feature::Springs},
                    .single_precision = true}},
      .keys = {{e, "velocity_iterations", KeyKind::Integer, 8, "velocity solver iterations"},
               {e, "position_iterations", KeyKind::Integer, 3, "position solver iterations"},
               {e, "linear_damping", KeyKind::Number, 0.0, "built-in linear damping, 1/s"},
               {e, "angular_damping", KeyKind::Number, 0.0, "built-in angular damping, 1/s"},
               {e, "restitution_threshold", KeyKind::Number, 1.0,
                "normal approach speed below which a contact does not bounce, m/s "
                "(b2FixtureDef::restitutionThreshold; Box2D's default)"},
               {e, "bullet", KeyKind::Boolean, 0.0,
                "continuous collision between moving bodies (b2BodyDef::bullet; Box2D's default "
                "is off)"}},
      .names_in_settings = {{"hinge", "b2RevoluteJoint"}}};
}

/// The description, made once: what the adapter reads its settings' defaults from.
inline const EngineDescription& box2d_description() {
  static const EngineDescription description = box2d_engine();
  return description;
}

}  // namespace bb
