// The push of the wind on a flat plate (seed sections 8 and 9): a plate is pushed along its
// normal n only, by the wind relative to it, v_a = w - v. One law for the sail and the wind
// panel, in the two forms the course text uses:
//   course    F = factor (v_a . n) n,             factor = k a (section 8's shape constant)
//   quadratic F = factor (v_a . n) |v_a . n| n,   factor = 1/2 rho C a (the drag formula)
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "model/world.hpp"

namespace bb {

/// The push on a plate whose unit normal is `n` in the relative wind `apparent`.
inline Vec3 flat_plate_push(PlateLaw law, double factor, const Vec3& apparent, const Vec3& n) {
  const double along = apparent.dot(n);
  return law == PlateLaw::Course ? factor * along * n : factor * along * std::abs(along) * n;
}

/// d(push)/d(the plate's velocity), n held: -factor n n^T, or -2 factor |v_a . n| n n^T.
inline Eigen::Matrix3d flat_plate_push_by_velocity(PlateLaw law, double factor,
                                                   const Vec3& apparent, const Vec3& n) {
  if (law == PlateLaw::Course) return -factor * n * n.transpose();
  return -2.0 * factor * std::abs(apparent.dot(n)) * n * n.transpose();
}

}  // namespace bb
