// The air forces of section 8 of the course text, as every backend applies them. Defined
// here so that every step that evaluates them (the course's, the reference's, each
// adapter's) inlines them: no call into the shared library per body.
#pragma once

#include "scene/scene.hpp"

namespace bb {

/// Quadratic drag F = -1/2 Cd A rho |v - w| (v - w), A = pi r^2 (newtons).
inline Vec3 drag_force(const Body& body, const Air& air, const Vec3& velocity) {
  const Vec3 relative = velocity - air.wind;
  const double k = 0.5 * body.drag_coefficient * frontal_area(body) * air.density;
  return relative * (-k * relative.norm());
}

/// Magnus force F = k (omega x (v - w)) (newtons).
inline Vec3 magnus_force(const Body& body, const Air& air, const Vec3& velocity,
                         const Vec3& omega) {
  return omega.cross(velocity - air.wind) * body.magnus;
}

/// The wind on a panel (seed section 8, the falling wall): a box with `wind_force` feels
/// its part along the normal n of the box's broad face (the axis of its smallest half
/// extent) turned by `q`, (F.n) n, at its centre (newtons).
inline Vec3 panel_wind_force(const Body& body, const Quat& q) {
  if (body.wind_force.isZero()) return Vec3::Zero();
  Eigen::Index thin = 0;
  body.half_extents.minCoeff(&thin);
  const Vec3 n = q * Vec3::Unit(thin);
  return n * body.wind_force.dot(n);
}

/// Sum of drag and Magnus on a body; zero when the scene has no air.
inline Vec3 air_force(const Scene& scene, const Body& body, const Vec3& velocity,
                      const Vec3& omega) {
  if (!scene.air) return Vec3::Zero();
  Vec3 force = Vec3::Zero();
  if (body.drag_coefficient > 0.0) force += drag_force(body, *scene.air, velocity);
  if (body.magnus != 0.0) force += magnus_force(body, *scene.air, velocity, omega);
  return force;
}

}  // namespace bb
