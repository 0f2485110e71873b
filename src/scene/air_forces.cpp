#include "scene/air_forces.hpp"

namespace bb {

Vec3 drag_force(const Body& body, const Air& air, const Vec3& velocity) {
  const Vec3 relative = velocity - air.wind;
  const double k = 0.5 * body.drag_coefficient * frontal_area(body) * air.density;
  return relative * (-k * relative.norm());
}

Vec3 magnus_force(const Body& body, const Air& air, const Vec3& velocity, const Vec3& omega) {
  return omega.cross(velocity - air.wind) * body.magnus;
}

Vec3 air_force(const Scene& scene, const Body& body, const Vec3& velocity, const Vec3& omega) {
  if (!scene.air) return {};
  Vec3 force;
  if (body.drag_coefficient > 0.0) force += drag_force(body, *scene.air, velocity);
  if (body.magnus != 0.0) force += magnus_force(body, *scene.air, velocity, omega);
  return force;
}

}  // namespace bb
