#include "run/cost.hpp"

#include <algorithm>
#include <chrono>

namespace bb {

Timing time_steps(const Backend& backend, const Scene& scene, double dt, long steps,
                  const CostOptions& options) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> samples;
  double total = 0.0;
  while (static_cast<int>(samples.size()) < options.max_repeats &&
         (static_cast<int>(samples.size()) < options.min_repeats || total < options.min_seconds)) {
    // Building the scene is outside the timer; only the step loop is inside.
    const auto sim = backend.start(scene, dt);
    const auto begin = Clock::now();
    for (long i = 0; i < steps; ++i) sim->step();
    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    samples.push_back(seconds);
    total += seconds;
  }
  std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
  return {samples[samples.size() / 2], static_cast<int>(samples.size())};
}

}  // namespace bb
