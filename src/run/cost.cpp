#include "run/cost.hpp"

#include <algorithm>
#include <chrono>

#include "study/start_case.hpp"

namespace bb {

namespace {

/// The most calls between two reads of the clock: beside 64 steps of a few nanoseconds,
/// reading it costs nothing.
constexpr long kMostCallsPerBlock = 64;
/// A block takes at most this share of max_seconds_per_repeat.
constexpr double kBlockShareOfRepeat = 1.0 / 16.0;

/// The next block after one of `block` calls, the calls so far taking `per_call` seconds
/// each: at most twice as many, at most kMostCallsPerBlock, at most what fits in
/// kBlockShareOfRepeat of a repeat, at least one.
long block_after(long block, double per_call, const CostOptions& options) {
  const double fits = kBlockShareOfRepeat * options.max_seconds_per_repeat / per_call;
  const long most =
      fits < static_cast<double>(kMostCallsPerBlock) ? static_cast<long>(fits) : kMostCallsPerBlock;
  return std::clamp(std::min(2 * block, most), 1L, kMostCallsPerBlock);
}

}  // namespace

Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options) {
  using Clock = std::chrono::steady_clock;
  // The clock is read once per block of calls, so that reading it costs nothing beside
  // a step of a few nanoseconds; the block starts at one call and grows as the calls show
  // how long a step takes (block_after), so that a slow step stops a repeat within a few
  // calls of max_seconds_per_repeat rather than a block of 64 later.
  long block = 1;
  std::vector<double> per_call;
  double total = 0.0;
  long most_calls = 0;
  int builds = 0;
  const auto started = Clock::now();
  const auto more = [&] {
    const int n = static_cast<int>(per_call.size());
    if (n == 0) return true;
    if (n >= options.max_repeats) return false;
    if (n >= options.min_repeats &&
        std::chrono::duration<double>(Clock::now() - started).count() >= options.max_wall_seconds)
      return false;
    return total < options.min_seconds ||
           (n < options.min_repeats && total < options.enough_seconds);
  };
  while (more()) {
    // Building the scene is outside the timer; only the step loop is inside.
    const auto sim = start_case(backend, scene, dt);
    ++builds;
    const auto begin = Clock::now();
    long calls = 0;
    double seconds = 0.0;
    // The whole run, or its first max_seconds_per_repeat of calls.
    while (calls < steps) {
      const long n = std::min(block, steps - calls);
      for (long i = 0; i < n; ++i) sim->step();
      calls += n;
      seconds = std::chrono::duration<double>(Clock::now() - begin).count();
      if (seconds >= options.max_seconds_per_repeat) break;
      block = block_after(block, seconds / static_cast<double>(calls), options);
    }
    per_call.push_back(seconds / static_cast<double>(std::max(calls, 1L)));
    most_calls = std::max(most_calls, calls);
    total += seconds;
  }
  std::nth_element(per_call.begin(), per_call.begin() + per_call.size() / 2, per_call.end());
  const auto [fastest, slowest] = std::minmax_element(per_call.begin(), per_call.end());
  const double calls = static_cast<double>(steps);
  return {per_call[per_call.size() / 2] * calls,
          static_cast<int>(per_call.size()),
          most_calls,
          *fastest * calls,
          *slowest * calls,
          total,
          builds};
}

bool timed_on_a_busy_machine(const Cost& cost) {
  return cost.repeats >= 3 && cost.ns_per_step_min > 0.0 &&
         cost.ns_per_step > kBusyMedianOverMin * cost.ns_per_step_min;
}

}  // namespace bb
