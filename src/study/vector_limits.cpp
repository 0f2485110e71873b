#include "study/vector_limits.hpp"

#include <cmath>
#include <string>

#include "model/text.hpp"

namespace bb {

const VectorLimit& vector_limit(VectorKind kind) {
  static const VectorLimit position{0.0, 1e6, "m", "a position"};
  static const VectorLimit velocity{0.0, 1e5, "m/s", "a velocity"};
  static const VectorLimit spin{0.0, 1e5, "rad/s", "an angular velocity"};
  static const VectorLimit direction{1e-9, 1e9, "", "a direction"};
  static const VectorLimit gravity{0.0, 1e4, "m/s^2", "gravity"};
  static const VectorLimit wind{0.0, 1e5, "m/s", "a wind"};
  static const VectorLimit force{0.0, 1e9, "N", "a force"};
  static const VectorLimit torque{0.0, 1e9, "N m", "a torque"};
  static const VectorLimit impulse{0.0, 1e9, "N s", "an impulse"};
  switch (kind) {
    case VectorKind::Position:
      return position;
    case VectorKind::Velocity:
      return velocity;
    case VectorKind::AngularVelocity:
      return spin;
    case VectorKind::Direction:
      return direction;
    case VectorKind::Gravity:
      return gravity;
    case VectorKind::Wind:
      return wind;
    case VectorKind::Force:
      return force;
    case VectorKind::Torque:
      return torque;
    case VectorKind::Impulse:
      break;
  }
  return impulse;
}

std::string vector_limit_problem(VectorKind kind, const Vec3& v) {
  const VectorLimit& limit = vector_limit(kind);
  // stableNorm: [0, 1e160, 0] is 1e160 long, not infinitely.
  const double norm = v.stableNorm();
  if (norm >= limit.least && norm <= limit.most) return "";
  const std::string unit = *limit.unit ? std::string(" ") + limit.unit : std::string();
  const std::string has = "has a norm of " + short_number(norm) + unit + "; ";
  if (kind == VectorKind::Direction)
    return has + limit.what + "'s norm is between " + short_number(limit.least) + " and " +
           short_number(limit.most) +
           " (it gives only a direction; beyond, its square "
           "underflows or overflows)";
  if (kind == VectorKind::Position)
    return has + limit.what + " is at most " + short_number(limit.most) + unit +
           " from the origin (beyond, a double no longer resolves the 1e-9 m that contacts "
           "are resolved to)";
  return has + limit.what + " is at most " + short_number(limit.most) + unit;
}

}  // namespace bb
