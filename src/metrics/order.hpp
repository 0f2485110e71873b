// Observed order of convergence: the least-squares slope of log(error) against log(dt), over
// the points in the asymptotic range only; otherwise no order, and why.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "metrics/trajectory.hpp"

namespace bb {

struct ErrorPoint {
  double dt;           ///< seconds
  double error;        ///< any error metric; NaN for a run that has none (it failed)
  double floor = 0.0;  ///< below this the error is noise, not truncation error
};

/// The error below which a run's differences from the reference are noise, in metres: ten
/// times the reference's self-check, or the rounding a run of `steps` steps can pile up on
/// `largest`, the largest position of the reference (half an ulp per step on the position
/// and as much again through the velocity: epsilon * largest * steps, at least 100 epsilon *
/// largest), with the machine epsilon of the run's arithmetic (double, or float for an
/// engine built in single precision).
double error_floor(double largest, double self_check, long steps,
                   double epsilon = std::numeric_limits<double>::epsilon());

/// The largest distance of any body from the origin over the trajectory's states (m).
double largest_position(const Trajectory& trajectory);
/// The largest distance any body moves from where it starts over the trajectory's states (m).
double largest_travel(const Trajectory& trajectory);

/// An error at or above this fraction of the motion's scale has saturated: a swing a
/// quarter of a period out of phase, a ball that fell through the ground. It no longer
/// shrinks as dt does, whatever the method's order.
inline constexpr double kSaturationFraction = 0.1;

/// A fitted slope below this is no order: the error is held by something other than the step.
inline constexpr double kSmallestOrder = 0.5;
/// A fit over three points (two local slopes) needs the two to agree within this fraction of
/// their mean: two cannot show whether the slopes are settling or drifting.
inline constexpr double kTwoSlopeAgreement = 0.1;

/// Local slopes of neighbouring points agree when they lie within this much of each other:
/// 0.25, or 15 percent of their mean, whichever is larger.
double slope_tolerance(double mean_slope);

/// The slope between two neighbouring steps of the sweep (both with an error above zero).
struct LocalSlope {
  double dt_small = 0.0, dt_large = 0.0;
  double slope = 0.0;
  bool in_fit = false;
};

struct OrderFit {
  std::optional<double> slope;           ///< nullopt unless three or more points are in the range
  int used = 0;                          ///< points in the fit
  int below_floor = 0;                   ///< points whose error is at or below their floor
  int saturated = 0;                     ///< points whose error is at or above the saturation level
  int failed = 0;                        ///< points with no error (the run diverged or failed)
  std::vector<LocalSlope> local_slopes;  ///< smallest dt first
  std::string reason;                    ///< why there is no order ("rounding: ...", ...)
};

/// The asymptotic range: starting from the smallest dt whose error lies between its floor
/// and `saturation`, the neighbouring steps upwards that are in that range too and whose
/// local slopes agree (slope_tolerance). With three points or more their least-squares slope
/// is the order, if it reaches kSmallestOrder; otherwise no order and the reason: "rounding"
/// (every error at its floor, or an error that grows as dt shrinks), "saturated", "not
/// asymptotic" (local slopes that disagree), "not converging", or too few points (with what
/// became of the others).
OrderFit fit_order(const std::vector<ErrorPoint>& points,
                   double saturation = std::numeric_limits<double>::infinity());

}  // namespace bb
