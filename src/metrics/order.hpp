// Observed order of convergence: the least-squares slope of log(error) against log(dt).
#pragma once

#include <optional>
#include <vector>

namespace bb {

struct ErrorPoint {
  double dt;     ///< seconds
  double error;  ///< any error metric
};

/// Slope fitted over the points whose error lies above `floor` (the reference's own error,
/// below which errors are noise); nullopt with fewer than two such points.
std::optional<double> fit_order(const std::vector<ErrorPoint>& points, double floor);

}  // namespace bb
