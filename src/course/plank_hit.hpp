// A ball hitting a plank (seed section 5, "The plank"), two ways:
// - seed_plank_hit, the seed's demo as written: the ball goes back with its full normal
//   speed, the plank takes the ball's momentum f = m_ball v_n as its own normal velocity
//   f / m_plank, and the torque r x f (an impulse, so "L = L + t") spins it, omega = L / J;
// - impulse_hit, a rigid-body impulse with restitution e at the contact point:
//   j = -(1 + e) v_rel.n / (1/m1 + 1/m2 + n.((J1^-1 (r1 x n)) x r1) + n.((J2^-1 (r2 x n)) x r2)),
//   which in 2D with a point ball is the (r x n)^2 / J, and keeps momentum and
//   angular momentum about any point.
#pragma once

#include <Eigen/Geometry>

namespace bb::course {

/// What a hit changes on one body: mass, inertia about its centre in the world frame,
/// centre, velocity and spin (world frame).
struct HitBody {
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();
};

/// The seed's shortcut: `ball` hits `plank` at `point` along the unit `normal` (from the
/// plank towards the ball). The plank's spin becomes L / J with L its angular momentum
/// plus the torque's impulse about its centre.
void seed_plank_hit(HitBody& ball, HitBody& plank, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal);

/// Newton's restitution with rigid bodies at `point`, `normal` from body b towards body a;
/// nothing happens when they separate there. Returns the impulse j (N s) along the normal.
double impulse_hit(HitBody& a, HitBody& b, const Eigen::Vector3d& point,
                   const Eigen::Vector3d& normal, double restitution);

/// Total linear momentum (N s), angular momentum about `origin` (N m s) and kinetic energy
/// (J, with the spin's part) of the bodies, for checking a hit.
Eigen::Vector3d momentum(const HitBody& a, const HitBody& b);
Eigen::Vector3d angular_momentum(const HitBody& a, const HitBody& b, const Eigen::Vector3d& origin);
double kinetic_energy(const HitBody& a, const HitBody& b);

}  // namespace bb::course
