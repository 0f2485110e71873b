// When one run is far off the others' scale (an exploding explicit Euler at 2800 m beside a
// cloth that moves 2 m, a rope stretched 490 times beside the others' 1.1), a plot sets its
// axes by the others, cuts that run at the edge and names it. The rule the trajectory plots,
// the sweep's panels and the motion view share: a run is off the scale when it leaves the
// guide's extent (the reference's) by more than kOffScale times the larger of the guide's
// span and the typical run's distance from it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace bb {

/// How many times the scale a run may leave the guide's extent before it is cut.
inline constexpr double kOffScale = 10.0;

/// The finite values an axis spans.
struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
  double span() const { return empty() ? 0.0 : hi - lo; }
  /// How far `v` lies outside, 0 inside.
  double beyond(double v) const {
    return empty() || !std::isfinite(v) ? 0.0 : std::max({0.0, lo - v, v - hi});
  }
};

/// The distance from the guide's extent past which a run is off the scale: kOffScale times
/// the largest of the guide's `span`, the typical (median) of every run's `reach` (how far
/// each leaves the guide's extent) and `floor` (the least scale the plot shows).
double off_scale_limit(std::vector<double> reach, double span, double floor);

}  // namespace bb
