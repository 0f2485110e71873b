// Observed order of convergence: the least-squares slope of log(error) against log(dt).
#pragma once

#include <optional>
#include <vector>

#include "metrics/trajectory.hpp"

namespace bb {

struct ErrorPoint {
  double dt;     ///< seconds
  double error;  ///< any error metric
};

/// The error below which differences are noise, not truncation error: ten times the
/// reference's self-check, or the rounding of a few hundred double operations on the
/// largest position in the reference, whichever is larger (metres).
double error_floor(const Trajectory& reference, double self_check);

/// Slope fitted over the points whose error lies above `floor` (the reference's own error,
/// below which errors are noise); nullopt with fewer than two such points.
std::optional<double> fit_order(const std::vector<ErrorPoint>& points, double floor);

}  // namespace bb
