#include "metrics/observables.hpp"

namespace bb {

ObservableValue measure(const Scene& scene, const Observe& observe, const Trajectory& trajectory) {
  (void)scene;
  if (trajectory.states.empty()) return {std::nullopt, "no samples"};
  if (observe.kind == "terminal_velocity") {
    // The speed at the end of the run.
    return {norm(trajectory.states.back()[observe.body].velocity), ""};
  }
  return {std::nullopt, "kind '" + observe.kind + "' is not measured by this version of beachball"};
}

}  // namespace bb
