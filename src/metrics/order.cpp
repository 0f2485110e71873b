#include "metrics/order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/text.hpp"

namespace bb {

namespace {

enum class Use { InRange, Rounding, Saturated, Failed };

/// "(2 at the floor, 1 saturated, 3 failed)", naming only what there is.
std::string others(const OrderFit& fit) {
  std::string out;
  const auto add = [&](int n, const char* what) {
    if (n > 0) out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(fit.below_floor, "at the rounding floor");
  add(fit.saturated, "saturated");
  add(fit.failed, "failed");
  return out.empty() ? "" : " (" + out + ")";
}

}  // namespace

double largest_position(const Trajectory& trajectory) {
  double largest = 0.0;
  for (const State& state : trajectory.states)
    for (const BodyState& b : state) largest = std::max(largest, b.position.norm());
  return largest;
}

double largest_travel(const Trajectory& trajectory) {
  double largest = 0.0;
  if (trajectory.states.empty()) return largest;
  const State& start = trajectory.states.front();
  for (const State& state : trajectory.states)
    for (std::size_t i = 0; i < state.size() && i < start.size(); ++i)
      largest = std::max(largest, (state[i].position - start[i].position).norm());
  return largest;
}

double error_floor(double largest, double self_check, long steps, double epsilon) {
  const double rounding = epsilon * largest * std::max(100.0, static_cast<double>(steps));
  return std::max(10.0 * self_check, rounding);
}

double slope_tolerance(double mean_slope) {
  return std::max(0.25, 0.15 * std::abs(mean_slope));
}

namespace {

/// The least-squares slope of log error against log dt over points [start, end).
double least_squares_slope(const std::vector<ErrorPoint>& points, std::size_t start,
                           std::size_t end) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = start; i < end; ++i) {
    const double x = std::log(points[i].dt), y = std::log(points[i].error);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// Why a run of `in_run` points in range, from `dt` up, is too short to fit: the error grows
/// as dt shrinks, the local slopes disagree, or there are too few points.
std::string short_run_reason(const OrderFit& fit, int in_run, double dt,
                             const std::vector<double>& slopes, std::optional<double> disagreeing) {
  const double opening = slopes.empty() ? disagreeing.value_or(0.0) : slopes.front();
  if (disagreeing && opening < 0.0)
    return "rounding: the error grows as dt shrinks (local slope " + significant_digits(opening) +
           " from " + significant_digits(dt) + " s)";
  if (disagreeing)
    return "not asymptotic: the local slopes from the smallest step in range, " +
           (slopes.empty() ? "" : significant_digits(slopes.front()) + " then ") +
           significant_digits(*disagreeing) + ", disagree";
  return "too few points: " + std::to_string(in_run) +
         " in a row between the rounding floor and saturation, three needed" + others(fit);
}

/// The points with a step, smallest dt first.
std::vector<ErrorPoint> sorted_by_dt(const std::vector<ErrorPoint>& input) {
  std::vector<ErrorPoint> points;
  for (const ErrorPoint& p : input)
    if (p.dt > 0.0) points.push_back(p);
  std::sort(points.begin(), points.end(),
            [](const ErrorPoint& a, const ErrorPoint& b) { return a.dt < b.dt; });
  return points;
}

/// What each point is to the fit, counted into `fit` by kind.
std::vector<Use> uses_of(const std::vector<ErrorPoint>& points, double saturation, OrderFit& fit) {
  std::vector<Use> use;
  for (const ErrorPoint& p : points) {
    const Use u = !std::isfinite(p.error) ? Use::Failed
                  : !(p.error > p.floor)  ? Use::Rounding
                  : p.error >= saturation ? Use::Saturated
                                          : Use::InRange;
    fit.failed += u == Use::Failed;
    fit.below_floor += u == Use::Rounding;
    fit.saturated += u == Use::Saturated;
    use.push_back(u);
  }
  return use;
}

/// The local slope between the points at `i` and `i + 1`.
double local_slope(const std::vector<ErrorPoint>& points, std::size_t i) {
  return std::log(points[i + 1].error / points[i].error) /
         std::log(points[i + 1].dt / points[i].dt);
}

/// Local slopes between neighbouring steps that both have an error above zero.
std::vector<LocalSlope> local_slopes(const std::vector<ErrorPoint>& points) {
  const auto measurable = [&](std::size_t i) {
    return std::isfinite(points[i].error) && points[i].error > 0.0;
  };
  std::vector<LocalSlope> out;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    if (measurable(i) && measurable(i + 1))
      out.push_back({points[i].dt, points[i + 1].dt, local_slope(points, i), false});
  return out;
}

/// Why no point is in range: none has an error, all are at the floor, all saturated, or a mix.
std::string no_range_reason(const OrderFit& fit, std::size_t points, double saturation) {
  return points == 0 || fit.failed == static_cast<int>(points) ? "no run with an error to fit"
         : fit.saturated == 0 && fit.failed == 0
             ? "rounding: every error is at or below its rounding floor"
         : fit.below_floor == 0 && fit.failed == 0
             ? "saturated: every error is at or above a tenth of the motion's scale (" +
                   significant_digits(saturation) + " m)"
             : "no error between the rounding floor and saturation" + others(fit);
}

/// The asymptotic run from `start`: its end (one past its last point), its local slopes, and
/// the first slope that disagreed with them, if one stopped it.
struct AgreeingRun {
  std::size_t end = 0;
  std::vector<double> slopes;
  std::optional<double> disagreeing;
};

/// From the smallest dt in range upwards, while the next step is in range and the local
/// slopes so far agree.
AgreeingRun agreeing_run(const std::vector<ErrorPoint>& points, const std::vector<Use>& use,
                         std::size_t start) {
  AgreeingRun run;
  run.end = start + 1;
  for (; run.end < points.size() && use[run.end] == Use::InRange; ++run.end) {
    run.slopes.push_back(local_slope(points, run.end - 1));
    const auto [low, high] = std::minmax_element(run.slopes.begin(), run.slopes.end());
    double mean = 0.0;
    for (double s : run.slopes) mean += s / static_cast<double>(run.slopes.size());
    if (*high - *low > slope_tolerance(mean)) {
      run.disagreeing = run.slopes.back();
      run.slopes.pop_back();
      break;
    }
  }
  return run;
}

}  // namespace

OrderFit fit_order(const std::vector<ErrorPoint>& input, double saturation) {
  OrderFit fit;
  const std::vector<ErrorPoint> points = sorted_by_dt(input);
  const std::vector<Use> use = uses_of(points, saturation, fit);
  fit.local_slopes = local_slopes(points);
  const auto first = std::find(use.begin(), use.end(), Use::InRange);
  if (first == use.end()) {
    fit.reason = no_range_reason(fit, points.size(), saturation);
    return fit;
  }
  const std::size_t start = static_cast<std::size_t>(first - use.begin());
  const AgreeingRun run = agreeing_run(points, use, start);
  const std::size_t end = run.end;
  const std::vector<double>& slopes = run.slopes;
  const int in_run = static_cast<int>(end - start);
  if (in_run < 3) {
    fit.reason = short_run_reason(fit, in_run, points[start].dt, slopes, run.disagreeing);
    return fit;
  }
  // Two local slopes cannot tell an order from a drift (1.19 then 1.32 on the way from 1.7
  // down to 1): they must agree to a tenth of their size.
  if (slopes.size() == 2 && std::abs(slopes[1] - slopes[0]) >
                                kTwoSlopeAgreement * 0.5 * std::abs(slopes[0] + slopes[1])) {
    fit.reason = "not asymptotic: only two local slopes in range, " +
                 significant_digits(slopes[0]) + " then " + significant_digits(slopes[1]) +
                 ", and they differ by more than a tenth: too few to tell an order from a drift";
    return fit;
  }
  const double fitted = least_squares_slope(points, start, end);
  // An error that does not shrink with dt is held by something other than the step.
  if (fitted < kSmallestOrder) {
    fit.reason = "not converging: the error barely shrinks with dt (slope " +
                 significant_digits(fitted) + " over the " + std::to_string(in_run) +
                 " smallest steps in range)";
    return fit;
  }
  fit.used = in_run;
  fit.slope = fitted;
  for (LocalSlope& s : fit.local_slopes)
    s.in_fit = s.dt_small >= points[start].dt && s.dt_large <= points[end - 1].dt;
  return fit;
}

}  // namespace bb
