// The matrix of a cross product, for the analytic Jacobians of the forces.
#pragma once

#include <Eigen/Core>

namespace bb {

/// skew(a) b = a x b.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

}  // namespace bb
