// A rigid body turning about a fixed world axis (a [[hinge]]), for the reference and the
// hinge force observable: it has one degree of freedom, the angle about the axis, and its
// centre moves on a circle about the anchor. Forces acting at the centre turn it through
// their torque about the axis.
#pragma once

#include <Eigen/Geometry>

#include "model/world.hpp"

namespace bb {

/// The moment of inertia (kg m^2) of `body`, turned by `q`, about the axis through
/// `anchor` along the unit `axis`, its centre at `centre`: J_c about the parallel axis
/// through the centre plus m d^2.
double axis_inertia(const Body& body, const Eigen::Quaterniond& q, const Eigen::Vector3d& centre,
                    const Hinge& hinge);

/// The accelerations of a hinged body whose centre is at `centre`, spinning at `spin`
/// about the axis, under `force` (N) at its centre: linear (m/s^2, the centre's) and
/// angular (rad/s^2).
struct HingeAccelerations {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};
HingeAccelerations hinge_accelerations(const Body& body, const Eigen::Quaterniond& q,
                                       const Eigen::Vector3d& centre, const Eigen::Vector3d& spin,
                                       const Eigen::Vector3d& force, const Hinge& hinge);

/// What an impulse `impulse` (N s) at world point `point` does to a hinged body: its spin
/// about the axis changes by the impulse's moment about the axis over axis_inertia, and its
/// centre's velocity follows, spin x (centre - anchor).
void hinge_impulse(const Body& body, const Eigen::Quaterniond& q, const Eigen::Vector3d& centre,
                   const Eigen::Vector3d& impulse, const Eigen::Vector3d& point, const Hinge& hinge,
                   Eigen::Vector3d& velocity, Eigen::Vector3d& spin);

}  // namespace bb
