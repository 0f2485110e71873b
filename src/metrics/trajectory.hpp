// A run's sampled states: one State per sample time.
#pragma once

#include <vector>

#include "model/state.hpp"
#include "seam/event_trace.hpp"

namespace bb {

struct Trajectory {
  std::vector<double> times;  ///< seconds, j * sample
  std::vector<State> states;  ///< one per time
  /// Contacts and apexes: found at every step, or located exactly by the reference.
  EventTrace events;
};

}  // namespace bb
