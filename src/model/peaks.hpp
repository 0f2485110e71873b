// The peak of a smooth quantity between two instants where it was seen, for observables
// that are a largest value over time (a spring's stretch): fixed-step runs find theirs
// between their steps with it, the reference prunes the spans it re-integrates with it.
#pragma once

#include <algorithm>
#include <cmath>

#include "model/vec3.hpp"

namespace bb {

/// A spring's relative extension (l - L) / L and its rate of change (1/s).
struct Stretch {
  double value = 0.0;
  double rate = 0.0;
};

/// The stretch of a spring of rest length `rest` (> 0) from point a to point b, whose ends
/// move at va and vb.
inline Stretch spring_stretch(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                              double rest) {
  const Vec3 d = xb - xa;
  const double length = d.norm();
  return {(length - rest) / rest, length > 0.0 ? d.dot(vb - va) / (length * rest) : 0.0};
}

/// The largest value over [0, h] of Hermite's cubic through (0, f0) and (h, f1) with slopes
/// r0 and r1 there: for a smooth quantity that rises at the start and falls at the end
/// (r0 > 0 > r1), its peak between the two, to fourth order in h.
inline double hermite_peak(double f0, double r0, double f1, double r1, double h) {
  // On s = t / h: p(s) = f0 + c s + b s^2 + a s^3, p'(s) = 3 a s^2 + 2 b s + c.
  const double c = h * r0;
  const double b = 3.0 * (f1 - f0) - h * (2.0 * r0 + r1);
  const double a = 2.0 * (f0 - f1) + h * (r0 + r1);
  const auto p = [&](double s) { return f0 + s * (c + s * (b + s * a)); };
  double best = std::max(f0, f1);
  const auto consider = [&](double s) {
    if (s > 0.0 && s < 1.0) best = std::max(best, p(s));
  };
  // The roots of p', written so that neither cancels (a may be zero: p is a parabola).
  const double discriminant = std::max(b * b - 3.0 * a * c, 0.0);
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q != 0.0) consider(c / q);
  if (a != 0.0) consider(q / (3.0 * a));
  return best;
}

}  // namespace bb
