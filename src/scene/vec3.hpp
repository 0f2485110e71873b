// Small value types for 3D vectors and unit quaternions, in double precision.
#pragma once

#include <cmath>

namespace bb {

/// A 3D vector; units depend on use (metres, metres per second, ...).
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  Vec3& operator*=(double s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  bool operator==(const Vec3&) const = default;
};

inline Vec3 operator+(Vec3 a, const Vec3& b) {
  return a += b;
}
inline Vec3 operator-(Vec3 a, const Vec3& b) {
  return a -= b;
}
inline Vec3 operator-(const Vec3& a) {
  return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(Vec3 a, double s) {
  return a *= s;
}
inline Vec3 operator*(double s, Vec3 a) {
  return a *= s;
}
inline Vec3 operator/(const Vec3& a, double s) {
  return {a.x / s, a.y / s, a.z / s};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
inline bool is_finite(const Vec3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// A rotation as a unit quaternion w + xi + yj + zk.
struct Quat {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  bool operator==(const Quat&) const = default;
};

inline Quat operator*(const Quat& a, const Quat& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

inline Quat normalized(const Quat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

inline Quat conjugate(const Quat& q) {
  return {q.w, -q.x, -q.y, -q.z};
}

/// `v` rotated by the unit quaternion `q`.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
  const Quat r = q * Quat{0.0, v.x, v.y, v.z} * conjugate(q);
  return {r.x, r.y, r.z};
}

/// Rotation by `angle` radians about the unit vector `axis`.
inline Quat quat_from_axis_angle(const Vec3& axis, double angle) {
  const double s = std::sin(angle / 2.0);
  return {std::cos(angle / 2.0), axis.x * s, axis.y * s, axis.z * s};
}

/// The rotation a constant angular velocity `omega` (rad/s, world frame) makes in `t` seconds.
inline Quat quat_from_rotation_vector(const Vec3& omega, double t) {
  const double rate = norm(omega);
  if (rate == 0.0) return {};
  return quat_from_axis_angle(omega / rate, rate * t);
}

/// Angle about z (radians) of a rotation that is about z, as in a 2D scene.
inline double angle_about_z(const Quat& q) {
  return 2.0 * std::atan2(q.z, q.w);
}

}  // namespace bb
