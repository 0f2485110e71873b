#include "metrics/order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bb {

double largest_position(const Trajectory& trajectory) {
  double largest = 0.0;
  for (const State& state : trajectory.states)
    for (const BodyState& b : state) largest = std::max(largest, b.position.norm());
  return largest;
}

double error_floor(double largest, double self_check, long steps) {
  const double rounding = std::numeric_limits<double>::epsilon() * largest *
                          std::max(100.0, static_cast<double>(steps));
  return std::max(10.0 * self_check, rounding);
}

OrderFit fit_order(const std::vector<ErrorPoint>& points) {
  OrderFit fit;
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ErrorPoint& p : points) {
    if (!std::isfinite(p.error) || p.dt <= 0.0) continue;
    if (!(p.error > p.floor)) {
      ++fit.below_floor;
      continue;
    }
    const double x = std::log(p.dt), y = std::log(p.error);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  fit.used = static_cast<int>(n);
  const double denominator = n * sxx - sx * sx;
  if (n >= 2 && denominator > 0.0) fit.slope = (n * sxy - sx * sy) / denominator;
  return fit;
}

}  // namespace bb
