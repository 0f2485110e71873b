#include "run/stability_watch.hpp"

#include <algorithm>
#include <cmath>

#include "study/case_limits.hpp"

namespace bb {

long StabilityWatch::trial_steps(const Scene& scene, double dt) {
  const long whole = static_cast<long>(std::ceil(scene.duration / dt - 1e-9));
  return std::max(whole, std::min(kMinTrialSteps, static_cast<long>(kMaxStepsPerRun)));
}

StabilityWatch::StabilityWatch(const Scene& scene, double dt, const State& start, long steps)
    : scene_(scene),
      bounds_(divergence_bounds(scene, std::max(scene.duration, static_cast<double>(steps) * dt),
                                kTrialStopEnergy)),
      energy_(scene) {
  steps_ = steps;
  // The energy's growth is judged after the last impulse, which may add energy at once.
  settled_ = scene.impulses.empty()
                 ? 0
                 : std::min(steps_, std::lround(scene.impulses.back().time / dt) + 1);
  judged_ = steps_ - settled_;
  windows_ = std::min<long>(kGrowthWindows, judged_);
  history_.scale = bounds_.scale.total();
  history_.level.reserve(windows_);
  history_.steps.reserve(windows_);
  e0_ = energy_(start);
}

bool StabilityWatch::observe(long n, const State& state) {
  if (diverged_ || n != observed_ + 1) return false;
  observed_ = n;
  const double energy = energy_(state);
  if (auto why = divergence(scene_, bounds_, state, e0_, energy)) {
    diverged_ = *why;
    return false;
  }
  if (n == settled_) e0_ = energy;
  if (n <= settled_) return true;
  largest_rise_ = std::max(largest_rise_, energy - e0_);
  // The end of window k of [settled, steps] comes after k / windows of its steps.
  const long k = static_cast<long>(history_.level.size()) + 1;
  if (n - settled_ == k * judged_ / windows_) {
    history_.level.push_back(largest_rise_);
    history_.steps.push_back(n - settled_);
  }
  return true;
}

std::optional<StabilityTrial> StabilityWatch::verdict() const {
  if (diverged_) return StabilityTrial{false, *diverged_, "diverged"};
  if (observed_ < steps_) return std::nullopt;
  const GrowthVerdict verdict = judge_growth(history_, scene_.stability.growth_factor);
  return StabilityTrial{verdict.stable, verdict.reason, growth_name(verdict.growth)};
}

}  // namespace bb
