// The height's wobble (seed section 8, "Wind": "given a significant rotation, the panel will
// move up and down in the air"), over the samples of the second half of the run, where a
// panel has taken up the wind and falls steadily: wobble_period (s) is the mean time between
// upward zero crossings of the vertical velocity less its mean there (a steady fall's rate
// taken out, every crossing moves alike and the spacing stays exact), wobble_amplitude (m)
// half the whole range of the height less its least-squares line there. A fall that is not
// steady there gets no value, with the reason. On the samples
// every backend and the reference share, so the values compare.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "observe/observable_measure.hpp"

namespace bb {

namespace {

/// The second half's times, heights and vertical velocities along -gravity, or the reason
/// there are none.
struct Rise {
  std::vector<double> times, heights, rates;
  std::string note;
};

Rise rise_of(const Scene& scene, const Observe& observe, const Trajectory& trajectory) {
  Rise r;
  if (scene.gravity.norm() == 0.0) {
    r.note = "no gravity: no height to wobble";
    return r;
  }
  const Vec3 up = -scene.gravity.normalized();
  const double half = trajectory.times.back() / 2.0;
  for (std::size_t j = 0; j < trajectory.times.size(); ++j) {
    if (trajectory.times[j] < half) continue;
    const BodyState& s = trajectory.states[j][observe.body];
    const double h = s.position.dot(up), v = s.velocity.dot(up);
    if (!std::isfinite(h) || !std::isfinite(v)) {
      r = {};
      r.note = "the height is not finite";
      return r;
    }
    r.times.push_back(trajectory.times[j]);
    r.heights.push_back(h);
    r.rates.push_back(v);
  }
  if (r.times.size() < 8) {
    r = {};
    r.note = "fewer than 8 samples in the second half of the run";
    return r;
  }
  // A fall still speeding up or slowing down has no steady rate to take out: the mean rate
  // of the window's two halves may differ by a quarter of the wobble's swing in rate at most.
  const std::size_t half_way = r.rates.size() / 2;
  const double first = std::accumulate(r.rates.begin(), r.rates.begin() + half_way, 0.0) /
                       static_cast<double>(half_way),
               second = std::accumulate(r.rates.begin() + half_way, r.rates.end(), 0.0) /
                        static_cast<double>(r.rates.size() - half_way);
  const auto [low, high] = std::minmax_element(r.rates.begin(), r.rates.end());
  const double swing = (*high - *low) / 2.0;
  if (std::abs(second - first) > 0.25 * swing) {
    const std::string note = fmt::format(
        "the fall is not steady in the second half of the run: its mean vertical speed changes "
        "by {:.3g} m/s there, against a wobble of {:.3g} m/s",
        std::abs(second - first), swing);
    r = {};
    r.note = note;
  }
  return r;
}

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace

ObservableValue measure_wobble_period(const Scene& scene, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace*) {
  const Rise r = rise_of(scene, observe, trajectory);
  if (r.times.empty()) return {std::nullopt, r.note};
  // Upward zero crossings of the rate less its mean, each interpolated between its samples.
  const double steady = mean(r.rates);
  std::vector<double> ups;
  for (std::size_t j = 1; j < r.rates.size(); ++j) {
    const double a = r.rates[j - 1] - steady, b = r.rates[j] - steady;
    if (a < 0.0 && b >= 0.0)
      ups.push_back(r.times[j - 1] + a / (a - b) * (r.times[j] - r.times[j - 1]));
  }
  if (ups.size() < 3)
    return {std::nullopt, "fewer than two whole wobbles in the second half of the run"};
  return {(ups.back() - ups.front()) / static_cast<double>(ups.size() - 1), ""};
}

ObservableValue measure_wobble_amplitude(const Scene& scene, const Observe& observe,
                                         const Trajectory& trajectory, const EventTrace*) {
  const Rise r = rise_of(scene, observe, trajectory);
  if (r.times.empty()) return {std::nullopt, r.note};
  // The least-squares line through the heights: the steady fall.
  const double t0 = mean(r.times), h0 = mean(r.heights);
  double tt = 0.0, th = 0.0;
  for (std::size_t j = 0; j < r.times.size(); ++j) {
    tt += (r.times[j] - t0) * (r.times[j] - t0);
    th += (r.times[j] - t0) * (r.heights[j] - h0);
  }
  const double slope = th / tt;
  double low = INFINITY, high = -INFINITY;
  for (std::size_t j = 0; j < r.times.size(); ++j) {
    const double rest = r.heights[j] - (h0 + slope * (r.times[j] - t0));
    low = std::min(low, rest), high = std::max(high, rest);
  }
  return {(high - low) / 2.0, ""};
}

}  // namespace bb
