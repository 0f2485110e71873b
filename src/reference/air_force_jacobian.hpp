// How the air's force on a body changes with its velocity and spin: the derivatives an
// implicit solver (msbdf) needs where drag makes a light body's fall stiff.
#pragma once

#include <Eigen/Core>

#include "scene/scene.hpp"

namespace bb {

struct AirForceJacobian {
  Eigen::Matrix3d by_velocity = Eigen::Matrix3d::Zero();  ///< dF/dv, N s/m
  Eigen::Matrix3d by_spin = Eigen::Matrix3d::Zero();      ///< dF/domega, N s
};

/// Derivatives of air_force() (drag -k|u|u and Magnus c omega x u, u = v - wind) at
/// velocity `v` and spin `omega`; zero when the scene has no air.
AirForceJacobian air_force_jacobian(const Scene& scene, const Body& body, const Eigen::Vector3d& v,
                                    const Eigen::Vector3d& omega);

}  // namespace bb
