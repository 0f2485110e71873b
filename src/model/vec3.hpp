// The project's vector and rotation types are Eigen's: Vec3 is Eigen::Vector3d and Quat is
// Eigen::Quaterniond (w, x, y, z). Every Eigen matrix starts at zero in this project
// (EIGEN_INITIALIZE_MATRICES_BY_ZERO, set for every target in the top CMakeLists.txt), and
// a Quat member is initialised to the identity where it is declared.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace bb {

/// A 3D vector; units depend on use (metres, metres per second, ...).
using Vec3 = Eigen::Vector3d;
/// A rotation as a unit quaternion w + xi + yj + zk.
using Quat = Eigen::Quaterniond;

/// `v` rotated by the unit quaternion `q`.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
  return q * v;
}

/// Rotation by `angle` radians about the unit vector `axis`.
inline Quat quat_from_axis_angle(const Vec3& axis, double angle) {
  return Quat(Eigen::AngleAxisd(angle, axis));
}

/// The rotation a constant angular velocity `omega` (rad/s, world frame) makes in `t` seconds.
inline Quat quat_from_rotation_vector(const Vec3& omega, double t) {
  const double rate = omega.norm();
  if (rate == 0.0) return Quat::Identity();
  return quat_from_axis_angle(omega / rate, rate * t);
}

/// Angle about z (radians, in (-pi, pi]) of a rotation that is about z, as in a 2D scene.
/// q and -q are the same rotation: taking w >= 0 keeps the angle within half a turn (else
/// 2 atan2(z, w) jumps by a whole 4 pi where w changes sign, and an unwrap by 2 pi loses a
/// turn there).
inline double angle_about_z(const Quat& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  return 2.0 * std::atan2(sign * q.z(), sign * q.w());
}

}  // namespace bb
