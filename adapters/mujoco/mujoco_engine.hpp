// MuJoCo as the harness knows it: `mujoco`, MuJoCo's own default integrator (Euler:
// velocities first, then positions with the new velocities), on free or hinged bodies, their
// contacts with the ground and with each other, with friction: the force stage (gravity is
// MuJoCo's own), impulses, rotation, boxes, 2D and 3D, and springs as tendons (not on
// mujoco/implicit). The same with MuJoCo's RK4 (`mujoco/rk4`) and its implicit integrator
// (`mujoco/implicit`).
#pragma once

#include "seam/engine_catalogue.hpp"

namespace bb {

inline FeatureSet mujoco_supports() {
  return force_stage_features() |
         FeatureSet{Feature::ThreeD,      Feature::Rotation,      Feature::Boxes,
                    Feature::Impulse,     Feature::GroundContact, Feature::BodyContact,
                    Feature::Restitution, Feature::Friction,      Feature::Hinge};
}

/// With springs, as MuJoCo tendons. Not for mujoco/implicit: MuJoCo 2.2.2's implicit step
/// forms the dense derivative of the velocity-dependent forces over every degree of freedom
/// at each step, which on the bundled spring grids costs more than the whole suite.
inline FeatureSet mujoco_supports_with_springs() {
  return mujoco_supports() | FeatureSet{Feature::Springs};
}

/// Why mujoco/rk4 does not step like semi-implicit Euler.
inline constexpr const char* kMujocoRk4Stages =
    "MuJoCo's RK4 computes its own forces (gravity, contacts, joints, the bias force) again at "
    "each of its four stages, while xfrc_applied, set once before the step, is held over them: "
    "the force model's forces (drag, Magnus, wind) enter at first order, and a cancelling "
    "gyroscopic torque cancels only at the step's start";

inline EngineDescription mujoco_engine() {
  const std::string e = "mujoco";
  return {.engine = e,
          .variants =
              {{.name = "mujoco", .colour = "#393a78", .supports = mujoco_supports_with_springs()},
               {.name = "mujoco/rk4",
                .colour = "#87a3eb",
                .supports = mujoco_supports_with_springs(),
                .staged_step = kMujocoRk4Stages},
               {.name = "mujoco/implicit", .colour = "#657b3a", .supports = mujoco_supports()}},
          .keys = {{e, "gyroscopic_term", KeyKind::Boolean, 1,
                    "the gyroscopic term w x I w of a free body, part of MuJoCo's bias force "
                    "qfrc_bias (on, as MuJoCo always has it); false cancels it with the opposite "
                    "torque through xfrc_applied before each step"}},
          .names_in_settings = {
              {"gyroscopic", "qfrc_bias"}, {"plane_2d", "slide joints"}, {"hinge", "hinge joint"}}};
}

/// The description, made once: what the adapter reads its settings' defaults from.
inline const EngineDescription& mujoco_description() {
  static const EngineDescription description = mujoco_engine();
  return description;
}

}  // namespace bb
