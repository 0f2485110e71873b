// ODE as the harness knows it: `ode` (springs as soft ODE joints) and `ode/force` (springs
// added by hand, on spring scenes only), its settings keys and their defaults.
#pragma once

#include "seam/engine_catalogue.hpp"

namespace bb {

/// Every feature.
inline FeatureSet ode_supports() {
  return force_stage_features() | FeatureSet{Feature::ThreeD,      Feature::Rotation,
                                             Feature::Boxes,       Feature::GroundContact,
                                             Feature::BodyContact, Feature::Restitution,
                                             Feature::Impulse,     Feature::Springs,
                                             Feature::Friction,    Feature::Hinge};
}

inline EngineDescription ode_engine() {
  const std::string e = "ode";
  return {
      .engine = e,
      .variants = {{.name = "ode", .colour = "#797e81", .supports = ode_supports()},
                   {.name = "ode/force",
                    .colour = "#bebe22",
                    .supports = ode_supports(),
                    .needs = {Feature::Springs}}},
      .keys =
          {{e, "erp", KeyKind::Number, 0.2, "error reduction parameter"},
           {e, "cfm", KeyKind::Number, 1e-5,
            "constraint force mixing of every contact and hinge row: beachball's 1e-5, as ODE's "
            "own demos set it, not ODE's default in double precision (cfm_ode_default)"},
           {e, "quick_step", KeyKind::Boolean, 0, "dWorldQuickStep instead of dWorldStep"},
           {e, "quick_step_iterations", KeyKind::Integer, 20, "iterations of dWorldQuickStep"},
           {e, "linear_damping", KeyKind::Number, 0.0, "built-in linear damping scale"},
           {e, "angular_damping", KeyKind::Number, 0.0, "built-in angular damping scale"},
           {e, "gyroscopic_term", KeyKind::Boolean, 1,
            "the gyroscopic term w x I w, linearly implicit: dBodySetGyroscopicMode(body, 1) "
            "on every moving body (ODE's default); false sets 0"},
           {e, "bounce_vel", KeyKind::Number, 0.1,
            "normal approach speed below which a contact does not bounce, m/s "
            "(dSurfaceParameters::bounce_vel; 0.1 as in ODE's own demos)"},
           {e, "contact_surface_layer", KeyKind::Number, 0.0,
            "depth contacts may sink before ERP pushes them out, m "
            "(dWorldSetContactSurfaceLayer; ODE's default)"}},
      .friction_pyramid = true,
      .names_in_settings = {{"gyroscopic", "dBodySetGyroscopicMode(body, 1)"},
                            {"hinge", "dJointCreateHinge"},
                            {"plane_2d", "put back in the plane"}},
      .hinge_numbers = {"hinge_erp", "hinge_cfm"}};
}

/// The description, made once: what the adapter reads its settings' defaults from.
inline const EngineDescription& ode_description() {
  static const EngineDescription description = ode_engine();
  return description;
}

}  // namespace bb
