#include "metrics/energy_growth.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "model/text.hpp"

namespace bb {

namespace {

/// Window-end positions (1-based) where quarter q (1 to 4) of `windows` starts and ends.
std::pair<int, int> quarter(int q, int windows) {
  const int from = std::max(1, static_cast<int>(std::lround((q - 1) * windows / 4.0)));
  return {from, static_cast<int>(std::lround(q * windows / 4.0))};
}

/// How much faster than steady drift the rise grew over quarter q: the log of its growth
/// factor less the log of the elapsed time's (0 for a rise proportional to time, (p - 1)
/// times that for t^p); nullopt when the quarter has no rise to start from.
std::optional<double> excess(const EnergyHistory& h, int q) {
  const auto [from, to] = quarter(q, static_cast<int>(h.level.size()));
  if (from >= to) return std::nullopt;
  const double a = h.level[from - 1], b = h.level[to - 1];
  if (!(a > 0.0) || h.steps[from - 1] <= 0) return std::nullopt;
  return std::log(b / a) -
         std::log(static_cast<double>(h.steps[to - 1]) / static_cast<double>(h.steps[from - 1]));
}

/// Whether the rise, in some quarter after the first, grew by less than the square root of
/// the elapsed time's factor: it stopped growing for a while, as steady drift never does.
bool levelled_off(const EnergyHistory& h) {
  const int windows = static_cast<int>(h.level.size());
  for (int q = 2; q <= 4; ++q) {
    const auto [from, to] = quarter(q, windows);
    const double a = h.level[from - 1], b = h.level[to - 1];
    if (from < to && a > 0.0 &&
        std::log(b / a) < 0.5 * std::log(static_cast<double>(h.steps[to - 1]) /
                                         static_cast<double>(h.steps[from - 1])))
      return true;
  }
  return false;
}

}  // namespace

std::string growth_name(Growth growth) {
  switch (growth) {
    case Growth::Bounded:
      return "bounded";
    case Growth::Drift:
      return "drift";
    case Growth::Compounds:
      return "compounds";
    case Growth::Runaway:
      return "runaway";
  }
  return "bounded";
}

namespace {

/// The verdict read from the whole run before its windows are looked at one by one: a
/// runaway held by the motion, or too few steps to tell; nothing when neither.
std::optional<GrowthVerdict> early_verdict(const EnergyHistory& whole) {
  const int all = static_cast<int>(whole.level.size());
  const double first = whole.level.front(), last = whole.level.back();
  if (last > kNearScale * whole.scale && last > 2.0 * first && levelled_off(whole))
    return GrowthVerdict{
        Growth::Runaway, false,
        "energy ran away: its rise above the start went from " + significant_digits(first) +
            " J at the end of the first of the run's " + std::to_string(all) + " windows to " +
            significant_digits(last) + " J, more than " + significant_digits(kNearScale) +
            " times the " + significant_digits(whole.scale) +
            " J the scene can put into motion, and levelled off on the way: held by the "
            "motion's nonlinearity (a spring folding through itself), not by the step"};
  // Too few steps to tell how it grows: only a rise far beyond the physics counts.
  if (all < kGrowthWindows) {
    const std::string few = "energy seen over too few steps (" + std::to_string(all) +
                            ") to tell how it grows; its rise above the start reached " +
                            significant_digits(last) + " J";
    if (last > kNearScale * whole.scale && last > 2.0 * first)
      return GrowthVerdict{Growth::Runaway, false,
                           few + ", more than " + significant_digits(kNearScale) + " times the " +
                               significant_digits(whole.scale) +
                               " J the scene can put into motion, from " +
                               significant_digits(first) + " J after its first step"};
    return GrowthVerdict{Growth::Bounded, true, few};
  }
  return std::nullopt;
}

/// The history from when the rise began, time counted from there: energy kept exactly until
/// a collision, say.
EnergyHistory from_rise(const EnergyHistory& whole) {
  EnergyHistory h;
  long origin = 0;
  for (std::size_t k = 0; k < whole.level.size(); ++k) {
    if (h.level.empty() && !(whole.level[k] > 0.0)) {
      origin = whole.steps[k];
      continue;
    }
    h.level.push_back(whole.level[k]);
    h.steps.push_back(whole.steps[k] - origin);
  }
  return h;
}

}  // namespace

GrowthVerdict judge_growth(const EnergyHistory& whole, double growth_factor) {
  const int all = static_cast<int>(whole.level.size());
  if (all < 4) return {};
  const double last = whole.level.back();
  if (!(last > kGrowthNoise * whole.scale)) return {};

  if (auto verdict = early_verdict(whole)) return *verdict;
  const EnergyHistory h = from_rise(whole);
  const int windows = static_cast<int>(h.level.size());
  if (windows < 4)
    return {Growth::Drift, true,
            "energy drifts: its rise above the start began in the last " + std::to_string(windows) +
                " of the run's " + std::to_string(all) +
                " windows, too late to tell how it grows, and reached " + significant_digits(last) +
                " J"};
  // Two quarters in a row. The first quarter also holds how the motion starts (a transient,
  // a swing building up): growth there counts only from twice what steady drift gives.
  const double threshold = std::log(growth_factor);
  for (int q = 2; q <= 4; ++q) {
    const auto before = excess(h, q - 1), now = excess(h, q);
    const double first_threshold = q == 2 ? std::max(threshold, std::log(2.0)) : threshold;
    if (!before || !now || *before <= first_threshold || *now <= threshold || *now < 0.85 * *before)
      continue;
    const int from = quarter(q - 1, windows).first, to = quarter(q, windows).second;
    return {
        Growth::Compounds, false,
        "energy grows without bound, compounding: over quarters " + std::to_string(q - 1) +
            " and " + std::to_string(q) + " of the run its rise above the start grew " +
            significant_digits(std::exp(*before)) + " and " + significant_digits(std::exp(*now)) +
            " times faster than steady drift would, from " + significant_digits(h.level[from - 1]) +
            " J to " + significant_digits(h.level[to - 1]) + " J" +
            (to < windows ? ", and " + significant_digits(last) + " J at the end" : "")};
  }
  // The rise in the last quarter, beside the whole rise: under 5 percent is levelling off,
  // near the scene's own scale (a level far above it is held by something else).
  if (last - whole.level[quarter(4, all).first - 1] <= 0.05 * last) {
    if (last > kNearScale * whole.scale && last > 2.0 * whole.level.front())
      return {Growth::Runaway, false,
              "energy levelled off far from the scene's scale: its rise above the start grew "
              "from " +
                  significant_digits(whole.level.front()) + " J to " + significant_digits(last) +
                  " J, more than " + significant_digits(kNearScale) + " times the " +
                  significant_digits(whole.scale) + " J the scene can put into motion"};
    return {Growth::Bounded, true,
            "energy bounded: its rise above the start levelled off at " + significant_digits(last) +
                " J"};
  }

  // How it grew over the second half, as a power of the elapsed time (when it had begun).
  const int half = windows / 2;
  const double middle = h.level[half - 1];
  const std::string power =
      middle > 0.0 ? ", as the elapsed time to the power " +
                         significant_digits(std::log(last / middle) /
                                            std::log(static_cast<double>(h.steps.back()) /
                                                     static_cast<double>(h.steps[half - 1]))) +
                         " over the second half"
                   : "";
  // Drift that carries the energy far past all the scene can put into motion is not bounded.
  if (last > kNearScale * whole.scale)
    return {Growth::Runaway, false,
            "energy drifts without bound: its rise above the start grew to " +
                significant_digits(last) + " J" + power + ", past " +
                significant_digits(kNearScale) + " times the " + significant_digits(whole.scale) +
                " J the scene can put into motion"};
  return {Growth::Drift, true,
          "energy drifts: its rise above the start grew to " + significant_digits(last) + " J" +
              power + ": drift that adds, not growth that compounds"};
}

}  // namespace bb
