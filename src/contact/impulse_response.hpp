// What an impulse J does to a free rigid body: its velocity changes by J / m and, when J
// acts off the centre at r, its spin by I^-1 (r x J), with I the inertia in the world frame.
#pragma once

#include <Eigen/Geometry>

#include "model/world.hpp"

namespace bb::contact {

/// Changes `velocity` and `spin` (world frame) of `body`, at `position` and `orientation`,
/// by the impulse `impulse` (N s) acting at the world point `point` (its centre when null).
void apply_impulse(const Body& body, const Eigen::Vector3d& impulse, const Eigen::Vector3d* point,
                   const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                   Eigen::Vector3d& velocity, Eigen::Vector3d& spin);

/// The same for one of the scene's [[impulse]] entries.
void apply_impulse(const Body& body, const Impulse& impulse, const Eigen::Vector3d& position,
                   const Eigen::Quaterniond& orientation, Eigen::Vector3d& velocity,
                   Eigen::Vector3d& spin);

}  // namespace bb::contact
