#include "metrics/order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bb {

double error_floor(const Trajectory& reference, double self_check) {
  double largest = 0.0;
  for (const State& state : reference.states)
    for (const BodyState& b : state) largest = std::max(largest, norm(b.position));
  return std::max(10.0 * self_check, 100.0 * std::numeric_limits<double>::epsilon() * largest);
}

std::optional<double> fit_order(const std::vector<ErrorPoint>& points, double floor) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ErrorPoint& p : points) {
    if (!(p.error > floor) || !std::isfinite(p.error) || p.dt <= 0.0) continue;
    const double x = std::log(p.dt), y = std::log(p.error);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator <= 0.0) return std::nullopt;
  return (n * sxy - sx * sy) / denominator;
}

}  // namespace bb
