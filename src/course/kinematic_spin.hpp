// The course text's kinematic rotation (seed section 5, "Kinematic rotation", "Double
// bounce 2", "Many beachballs"): no torque, no friction. A ball that hits a surface is
// given the spin of rolling along it, and two balls that touch may share their spins by the
// seed's rule. The ball's velocity is left as it is.
#pragma once

#include <Eigen/Geometry>
#include <string>

namespace bb::course {

/// Which spin a ball gets at its contacts.
enum class SpinRule {
  Free,       ///< none set: a ball keeps the spin it has (torque-free)
  Kinematic,  ///< SetRotation at the ground and fixed bodies ("Many beachballs bad")
  Shared,     ///< that, and two touching balls share their spins ("Many beachballs")
};

/// The rule called `name` ("free", "kinematic", "shared"); throws std::invalid_argument.
SpinRule spin_rule(const std::string& name);

/// The seed's SetRotation: a ball of `radius` moving at `velocity` that hits a surface with
/// unit `normal` spins at |v_t| / r about v x n, turned the way that rolls it along the
/// surface; zero when it moves along the normal. The seed sets this turn per frame with "no
/// consideration of dt"; here it is a spin in rad/s, the rolling rate the seed aims at.
Eigen::Vector3d contact_spin(const Eigen::Vector3d& velocity, const Eigen::Vector3d& normal,
                             double radius);

/// The seed's rule for two touching balls: each spin is read back from its per-step turn,
/// then the first gets half their difference and the second its opposite. Reading the turn
/// back, the seed's MatrixToVec3 returns no spin when 2 sin of the step's angle is below
/// 0.001; that threshold is kept, so a slow spin at a short dt reads as none.
void share_spins(Eigen::Vector3d& first, Eigen::Vector3d& second, double dt);

}  // namespace bb::course
