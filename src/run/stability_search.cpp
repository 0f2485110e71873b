#include "run/stability_search.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace bb {

namespace {

/// Two steps closer than this ratio count as one (a probe on a step already tried).
constexpr double kSameStep = 1.005;

}  // namespace

bool StabilitySearch::all_unstable() const {
  return std::none_of(tried_.begin(), tried_.end(), [](const Tried& t) { return t.trial.stable; });
}

bool StabilitySearch::needs_bottom() const {
  return !tried_.empty() && !tried_.front().trial.stable && tried_.front().dt > dt_min_;
}

std::optional<double> StabilitySearch::narrowing() const {
  bool lowest = true;
  for (std::size_t i = 0; i + 1 < tried_.size(); ++i) {
    const Tried &a = tried_[i], &b = tried_[i + 1];
    if (a.trial.stable == b.trial.stable) continue;
    // The lowest change of verdict sets the largest safe step: it is narrowed the most.
    if (b.dt / a.dt > (lowest ? 1.001 : 1.01)) return std::sqrt(a.dt * b.dt);
    lowest = false;
  }
  return std::nullopt;
}

std::optional<double> StabilitySearch::next() const {
  if (static_cast<int>(tried_.size()) >= kMaxTrials) return std::nullopt;
  if (tried_.empty()) return dt_max_;
  if (needs_bottom()) return dt_min_;
  if (all_unstable()) return std::nullopt;
  if (!probes_.empty()) return probes_.front();
  return narrowing();
}

void StabilitySearch::queue_probes() {
  probed_ = true;
  // The step found: the largest stable step below the smallest unstable one.
  double found = 0.0;
  for (const Tried& t : tried_) {
    if (!t.trial.stable) break;
    found = t.dt;
  }
  for (double fraction : kProbes) {
    const double dt = fraction * found;
    if (dt < dt_min_) continue;
    const bool tried = std::any_of(tried_.begin(), tried_.end(), [&](const Tried& t) {
      return std::max(t.dt, dt) / std::min(t.dt, dt) < kSameStep;
    });
    if (!tried) probes_.push_back(dt);
  }
}

void StabilitySearch::record(double dt, const StabilityTrial& trial) {
  const auto at = std::lower_bound(tried_.begin(), tried_.end(), dt,
                                   [](const Tried& t, double d) { return t.dt < d; });
  tried_.insert(at, {dt, trial});
  std::erase(probes_, dt);
  // Once the first bracket is narrowed, check below it.
  if (!probed_ && !needs_bottom() && !all_unstable() && !narrowing()) queue_probes();
}

std::vector<double> StabilitySearch::likely_next(int count,
                                                 const std::function<Known(double)>& known) const {
  std::vector<double> out;
  // Breadth first over supposed verdicts: the nearer a step, the likelier it is asked for.
  std::deque<std::pair<StabilitySearch, int>> open{{*this, 0}};
  while (!open.empty() && static_cast<int>(out.size()) < count) {
    const auto [search, depth] = std::move(open.front());
    open.pop_front();
    const std::optional<double> dt = search.next();
    if (!dt) continue;
    const Known k = known(*dt);
    if (k == Known::Nothing && std::find(out.begin(), out.end(), *dt) == out.end())
      out.push_back(*dt);
    if (depth >= kLookAhead) continue;
    for (const bool stable : {true, false}) {
      if ((k == Known::Stable && !stable) || (k == Known::Unstable && stable)) continue;
      StabilitySearch after = search;
      after.record(*dt, {stable, "", stable ? "bounded" : "diverged"});
      open.emplace_back(std::move(after), depth + 1);
    }
  }
  return out;
}

void StabilitySearch::fill(StabilityResult& r) const {
  r.trials = static_cast<int>(tried_.size());
  r.bands.clear();
  for (const Tried& t : tried_) {
    if (r.bands.empty() || r.bands.back().stable != t.trial.stable)
      r.bands.push_back({t.dt, t.dt, t.trial.stable, t.trial.stable ? "" : t.trial.reason});
    StabilityBand& band = r.bands.back();
    band.to = t.dt;
    // A stable band says what its largest step's energy did, if anything.
    if (t.trial.stable) band.reason = t.trial.reason;
  }
  if (r.bands.empty()) return;
  const StabilityBand& first = r.bands.front();
  if (r.bands.size() == 1) {
    r.status = first.stable ? "stable at every dt tried" : "unstable at every dt tried";
    if (first.stable) r.critical_dt = first.to, r.stable_note = first.reason;
    if (!first.stable) r.unstable_dt = first.from, r.reason = first.reason;
    return;
  }
  r.status = r.bands.size() == 2 && first.stable ? "bracketed" : "not monotone";
  if (first.stable) r.critical_dt = first.to, r.stable_note = first.reason;
  const StabilityBand& unstable = first.stable ? r.bands[1] : first;
  r.unstable_dt = unstable.from;
  r.reason = unstable.reason;
}

}  // namespace bb
