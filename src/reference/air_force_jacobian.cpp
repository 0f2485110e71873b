#include "reference/air_force_jacobian.hpp"

#include "reference/cross_matrix.hpp"

namespace bb {

AirForceJacobian air_force_jacobian(const Scene& scene, const Body& body, const Eigen::Vector3d& v,
                                    const Eigen::Vector3d& omega) {
  AirForceJacobian j;
  if (!scene.air) return j;
  const Eigen::Vector3d u = v - scene.air->wind;
  if (body.drag_coefficient > 0.0) {
    // d(-k |u| u)/du = -k (|u| I + u u^T / |u|), which vanishes as u goes to zero.
    const double k = 0.5 * body.drag_coefficient * frontal_area(body) * scene.air->density;
    const double speed = u.norm();
    if (speed > 0.0)
      j.by_velocity -= k * (speed * Eigen::Matrix3d::Identity() + u * u.transpose() / speed);
  }
  if (body.magnus != 0.0) {
    // d(c omega x u)/du = c skew(omega); d(c omega x u)/domega = -c skew(u).
    j.by_velocity += body.magnus * skew(omega);
    j.by_spin -= body.magnus * skew(u);
  }
  return j;
}

}  // namespace bb
