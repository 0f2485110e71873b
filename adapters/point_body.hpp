// How every engine adapter stands in for a point body: engines need a positive mass and
// inertia (ODE's dMassCheck aborts on zero), so a point becomes a small solid sphere.
#pragma once

#include <algorithm>
#include <string>

#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// Radius, in metres, of the sphere that stands in for a point body. Its only use is the
/// inertia: a sphere's inertia is the same about every axis and nothing applies a torque
/// to a point (no contacts, no Magnus), so its spin stays constant and the radius does not
/// change any result. 1 cm keeps the inertia small and positive for any mass.
inline constexpr double kPointBodyRadius = 0.01;

/// The inertia (kg m^2) an engine gets for `body`: a point's is that of a solid sphere of
/// kPointBodyRadius with the point's mass, 2/5 m r^2; other shapes keep their own.
inline Vec3 engine_inertia(const Body& body) {
  if (body.shape != Shape::Point) return principal_inertia(body);
  const double i = 0.4 * body.mass * kPointBodyRadius * kPointBodyRadius;
  return {i, i, i};
}

/// The inertia tensor (kg m^2, world frame) an engine gets for `body` turned to
/// `orientation`: R diag(I) R^T, for an impulse's turn or a torque computed by hand.
inline Eigen::Matrix3d engine_world_inertia(const Body& body, const Quat& orientation) {
  const Eigen::Matrix3d r = orientation.normalized().toRotationMatrix();
  return r * engine_inertia(body).asDiagonal() * r.transpose();
}

/// Adds the "point_body" engine setting when the scene has a non-fixed point body.
inline void add_point_body_setting(const World& scene, Settings& settings) {
  const bool any = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                               [](const Body& b) { return b.shape == Shape::Point && !b.fixed; });
  // The radius in the text is kPointBodyRadius.
  if (any)
    settings.push_back({"point_body", std::string("solid sphere of radius 0.01 m with the "
                                                  "point's mass, for mass and inertia; "
                                                  "no collisions")});
}

}  // namespace bb
