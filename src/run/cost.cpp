#include "run/cost.hpp"

#include <algorithm>
#include <chrono>

namespace bb {

Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options) {
  using Clock = std::chrono::steady_clock;
  // The clock is read once per block of calls, so that reading it costs nothing beside
  // a step of a few nanoseconds.
  constexpr long kBlock = 64;
  std::vector<double> per_call;
  double total = 0.0;
  long most_calls = 0;
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
    const auto sim = backend.start(scene, dt);
    const auto begin = Clock::now();
    long calls = 0;
    double seconds = 0.0;
    // The whole run, or its first max_seconds_per_repeat of calls.
    while (calls < steps) {
      const long block = std::min(kBlock, steps - calls);
      for (long i = 0; i < block; ++i) sim->step();
      calls += block;
      seconds = std::chrono::duration<double>(Clock::now() - begin).count();
      if (seconds >= options.max_seconds_per_repeat) break;
    }
    per_call.push_back(seconds / static_cast<double>(std::max(calls, 1L)));
    most_calls = std::max(most_calls, calls);
    total += seconds;
  }
  std::nth_element(per_call.begin(), per_call.begin() + per_call.size() / 2, per_call.end());
  const auto [fastest, slowest] = std::minmax_element(per_call.begin(), per_call.end());
  const double calls = static_cast<double>(steps);
  return {per_call[per_call.size() / 2] * calls, static_cast<int>(per_call.size()), most_calls,
          *fastest * calls, *slowest * calls};
}

bool timed_on_a_busy_machine(const Cost& cost) {
  return cost.repeats >= 3 && cost.ns_per_step_min > 0.0 &&
         cost.ns_per_step > kBusyMedianOverMin * cost.ns_per_step_min;
}

}  // namespace bb
