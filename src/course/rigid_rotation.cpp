#include "course/rigid_rotation.hpp"

#include "model/vec3.hpp"

namespace bb::course {

void rotate_rigid(const Eigen::Vector3d& principal, const Eigen::Vector3d& torque, double dt,
                  Eigen::Vector3d& momentum, Eigen::Quaterniond& orientation,
                  Eigen::Vector3d& spin) {
  momentum += torque * dt;
  // The spin from the inertia as the body stands at the step's start.
  spin = world_inertia(principal, orientation).ldlt().solve(momentum);
  // Turned on the left, as the seed multiplies its rotation: the spin is in the world frame.
  orientation = (quat_from_rotation_vector(spin, dt) * orientation).normalized();
  // The spin the body has as it now stands, with the same L: what a reader of the state
  // sees, and what its energy is made of.
  spin = world_inertia(principal, orientation).ldlt().solve(momentum);
}

}  // namespace bb::course
