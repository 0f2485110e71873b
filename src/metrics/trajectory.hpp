// A run's sampled states: one State per sample time.
#pragma once

#include <vector>

#include "scene/state.hpp"

namespace bb {

struct Trajectory {
  std::vector<double> times;  ///< seconds, j * sample
  std::vector<State> states;  ///< one per time
};

}  // namespace bb
