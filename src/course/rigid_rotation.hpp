// The course text's rotation with physics (seed section 5): torque adds to the angular
// momentum, L += T dt; the inverse inertia, turned into the world frame, gives the spin,
// omega = J^-1 L; the orientation turns by that spin over the step and is re-normalised.
// In 2D (a turn about z only) this is the seed's scalar sequence L += T dt, omega = L / J,
// angle += omega dt. Unlike the kinematic rotation of spheres (a spin kept as it is), a
// body whose inertia differs along its axes changes its spin as it turns, with L fixed.
#pragma once

#include <Eigen/Geometry>

namespace bb::course {

/// The inertia (kg m^2) in the world frame of a body with `principal` moments turned by `q`.
inline Eigen::Matrix3d world_inertia(const Eigen::Vector3d& principal,
                                     const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  return r * principal.asDiagonal() * r.transpose();
}

/// One step of `dt` seconds for a rigid body with `principal` moments of inertia under
/// `torque` (N m, world frame): `momentum` (L, world frame) and `orientation` advance, the
/// turn made with the spin J^-1 L of the step's start; `spin` becomes J^-1 L as the body
/// stands at the step's end.
void rotate_rigid(const Eigen::Vector3d& principal, const Eigen::Vector3d& torque, double dt,
                  Eigen::Vector3d& momentum, Eigen::Quaterniond& orientation,
                  Eigen::Vector3d& spin);

}  // namespace bb::course
