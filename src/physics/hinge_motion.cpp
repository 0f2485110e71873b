#include "physics/hinge_motion.hpp"

namespace bb {

double axis_inertia(const Body& body, const Eigen::Quaterniond& q, const Eigen::Vector3d& centre,
                    const Hinge& hinge) {
  const Eigen::Vector3d u = hinge.axis, r = centre - hinge.anchor;
  const Eigen::Matrix3d rot = q.normalized().toRotationMatrix();
  const Eigen::Vector3d local = rot.transpose() * u;
  const double about_centre = local.dot(principal_inertia(body).asDiagonal() * local);
  const Eigen::Vector3d across = r - r.dot(u) * u;
  return about_centre + body.mass * across.squaredNorm();
}

HingeAccelerations hinge_accelerations(const Body& body, const Eigen::Quaterniond& q,
                                       const Eigen::Vector3d& centre, const Eigen::Vector3d& spin,
                                       const Eigen::Vector3d& force, const Hinge& hinge) {
  const Eigen::Vector3d u = hinge.axis, r = centre - hinge.anchor;
  const double alpha = r.cross(force).dot(u) / axis_inertia(body, q, centre, hinge);
  HingeAccelerations out;
  out.angular = alpha * u;
  // Tangential from the angular acceleration, centripetal from the spin.
  out.linear = out.angular.cross(r) + spin.cross(spin.cross(r));
  return out;
}

void hinge_impulse(const Body& body, const Eigen::Quaterniond& q, const Eigen::Vector3d& centre,
                   const Eigen::Vector3d& impulse, const Eigen::Vector3d& point, const Hinge& hinge,
                   Eigen::Vector3d& velocity, Eigen::Vector3d& spin) {
  const Eigen::Vector3d u = hinge.axis;
  const double moment = (point - hinge.anchor).cross(impulse).dot(u);
  spin += moment / axis_inertia(body, q, centre, hinge) * u;
  velocity = spin.cross(centre - hinge.anchor);
}

}  // namespace bb
