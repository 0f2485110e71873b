// The plank on an axis (seed section 5, "the same plank but this time anchored by an
// axis"): the seed splits the plank at the axis into two rods turning about their ends,
// 1/3 m d1^2 + 1/3 m d2^2, giving each side the whole plank's mass. Beside it, a uniform
// plank's inertia about the axis by the parallel-axis theorem, 1/12 m l^2 + m a^2.
#pragma once

namespace bb::course {

/// The seed's formula for a plank of mass m (kg) and length l (m) on an axis `a` metres
/// from its centre: d1 = l/2 - a, d2 = l/2 + a, J = m d1^2 / 3 + m d2^2 / 3 (kg m^2).
inline double seed_axis_inertia(double m, double l, double a) {
  const double d1 = 0.5 * l - a, d2 = 0.5 * l + a;
  return m * d1 * d1 / 3.0 + m * d2 * d2 / 3.0;
}

/// A uniform plank's inertia about the same axis: 1/12 m l^2 + m a^2 (kg m^2).
inline double plank_axis_inertia(double m, double l, double a) {
  return m * l * l / 12.0 + m * a * a;
}

}  // namespace bb::course
