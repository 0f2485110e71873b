// surface_fold (ratio): how far a [waves] surface is from folding over, the least, over the
// samples and over neighbouring surface points, of (x_{i+1} - x_i) / (x0_{i+1} - x0_i): 1
// for a flat surface, 1 - amplitude k for Gerstner's (the circles' phase makes d x / d x0 =
// 1 - amplitude k sin(phase)), 0 where two neighbours meet, negative where the surface has
// folded over itself (seed section 10: "the wave deteriorates and self-intersects").
#include <algorithm>
#include <limits>

#include "observe/observable_measure.hpp"

namespace bb {

ObservableValue measure_surface_fold(const Scene& scene, const Observe&,
                                     const Trajectory& trajectory, const EventTrace*) {
  if (!scene.waves) return {std::nullopt, "the case has no [waves] surface"};
  const Waves& w = *scene.waves;
  const double spacing = (w.to - w.from) / (w.points - 1);
  double least = std::numeric_limits<double>::infinity();
  for (const State& state : trajectory.states)
    for (int i = w.first_body; i + 1 < w.first_body + w.points; ++i) {
      const double dx = state[static_cast<std::size_t>(i + 1)].position.x() -
                        state[static_cast<std::size_t>(i)].position.x();
      least = std::min(least, dx / spacing);
    }
  return {least, ""};
}

}  // namespace bb
