// Observed order of convergence: the least-squares slope of log(error) against log(dt).
#pragma once

#include <optional>
#include <vector>

#include "metrics/trajectory.hpp"

namespace bb {

struct ErrorPoint {
  double dt;           ///< seconds
  double error;        ///< any error metric
  double floor = 0.0;  ///< below this the error is noise, not truncation error
};

/// The error below which a run's differences from the reference are noise, in metres: ten
/// times the reference's self-check, or the rounding a run of `steps` steps can pile up on
/// `largest`, the largest position of the reference (half an ulp per step on the position
/// and as much again through the velocity: eps * largest * steps, at least 100 eps *
/// largest).
double error_floor(double largest, double self_check, long steps);

/// The largest distance of any body from the origin over the trajectory's states (m).
double largest_position(const Trajectory& trajectory);

struct OrderFit {
  std::optional<double> slope;  ///< nullopt with fewer than two points above their floor
  int used = 0;                 ///< points in the fit
  int below_floor = 0;          ///< points left out because their error is at or below floor
};

/// Slope fitted over the points whose error lies above their floor; points that are not
/// finite are left out too (they count in neither number).
OrderFit fit_order(const std::vector<ErrorPoint>& points);

}  // namespace bb
