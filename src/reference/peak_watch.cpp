#include "reference/peak_watch.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_pairs.hpp"
#include "reference/scene_model_state.hpp"

namespace bb {

using namespace state_view;

namespace {

/// Seconds: how closely a peak's time is located (as events are).
constexpr double kPeakTimeTolerance = 1e-12;

}  // namespace

PeakWatch::PeakWatch(const World& scene, const EventWatches& events, const std::vector<double>& y0)
    : scene_(scene),
      stretch_(events.stretch),
      springs_(events.springs),
      penetration_(scene.bodies.size(), 0.0) {
  std::vector<bool> overlap_watched(scene.bodies.size(), false);
  for (int body : events.overlapping) overlap_watched[body] = true;
  for (const ContactPair& pair : contact_pairs(scene))
    if (overlap_watched[pair.a] || (!pair.ground() && overlap_watched[pair.b]))
      pairs_.push_back(pair);
  for (std::size_t k = 0; k < springs_.size(); ++k)
    max_stretch_ = std::max(max_stretch_, stretch(k, y0.data()).value);
  overlaps(y0.data());
}

Stretch PeakWatch::stretch(std::size_t k, const double* y) const {
  const Spring& s = scene_.springs[springs_[k]];
  return spring_stretch(position(y, s.body_a), position(y, s.body_b), velocity(y, s.body_a),
                        velocity(y, s.body_b), s.rest_length);
}

void PeakWatch::overlaps(const double* y) {
  for (const ContactPair& pair : pairs_) {
    const int b = pair.ground() ? pair.a : pair.b;
    const double gap = contact::measure(scene_, pair, position(y, pair.a), position(y, b),
                                        orientation(y, b).normalized())
                           .gap;
    if (gap >= 0.0) continue;
    penetration_[pair.a] = std::max(penetration_[pair.a], -gap);
    if (!pair.ground()) penetration_[pair.b] = std::max(penetration_[pair.b], -gap);
  }
}

double PeakWatch::locate_peak(HybridIntegrator& integrator, std::size_t k, double t0, double r0,
                              double t1, double r1) {
  // Illinois' regula falsi on the rate, which is positive at t0 and negative at t1. Every
  // value seen on the way is a value of the solution: the largest is the peak's.
  double best = -INFINITY;
  int side = 0;
  for (int n = 0; n < 100 && t1 - t0 > kPeakTimeTolerance; ++n) {
    double t = (t0 * r1 - t1 * r0) / (r1 - r0);
    if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
    integrator.dense_state(t, probe_);
    const Stretch s = stretch(k, probe_.data());
    best = std::max(best, s.value);
    if (s.rate > 0.0) {
      t0 = t, r0 = s.rate;
      if (side == -1) r1 *= 0.5;
      side = -1;
    } else {
      t1 = t, r1 = s.rate;
      if (side == +1) r0 *= 0.5;
      side = +1;
    }
  }
  return best;
}

void PeakWatch::span(HybridIntegrator& integrator, double t0, const double* y0, double t1,
                     const double* y1) {
  overlaps(y1);
  for (std::size_t k = 0; k < springs_.size(); ++k) {
    // At the span's start, after any event there changed the velocities.
    const Stretch start = stretch(k, y0), end = stretch(k, y1);
    max_stretch_ = std::max(max_stretch_, end.value);
    if (!(start.rate > 0.0 && end.rate < 0.0)) continue;
    // The cubic's bulge above the higher end estimates the peak to fourth order in the
    // span; twice it bounds what the peak may add, so a spring that cannot beat the
    // largest yet is not located.
    const double top = std::max(start.value, end.value);
    const double bulge = hermite_peak(start.value, start.rate, end.value, end.rate, t1 - t0) - top;
    if (top + 2.0 * bulge < max_stretch_) continue;
    max_stretch_ = std::max(max_stretch_, locate_peak(integrator, k, t0, start.rate, t1, end.rate));
  }
}

void PeakWatch::fill(EventTrace& trace) const {
  if (stretch_) trace.max_stretch = max_stretch_;
  for (const ContactPair& pair : pairs_)
    for (int body : {pair.a, pair.b})
      if (body >= 0) trace.bodies[body].max_penetration = penetration_[body];
}

}  // namespace bb
