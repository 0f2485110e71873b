// A ball hitting a plank (seed section 5, "The plank"), two ways:
// - seed_plank_hit, the seed's demo as written: the ball goes back with its full normal
//   speed, the plank takes the ball's momentum f = m_ball v_n as its own normal velocity
//   f / m_plank, and the torque r x f (an impulse, so "L = L + t") spins it, omega = L / J;
// - impulse_hit, a rigid-body impulse with restitution e at the contact point:
//   contact::impulse_hit (contact/rigid_hit.hpp), which keeps momentum and angular momentum
//   about any point.
#pragma once

#include "contact/rigid_hit.hpp"

namespace bb::course {

/// The seed's shortcut: `ball` hits `plank` at `point` along the unit `normal` (from the
/// plank towards the ball). The plank's spin becomes L / J with L its angular momentum
/// plus the torque's impulse about its centre.
void seed_plank_hit(contact::HitBody& ball, contact::HitBody& plank, const Eigen::Vector3d& point,
                    const Eigen::Vector3d& normal);

}  // namespace bb::course
