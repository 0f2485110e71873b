// max_speed (m/s): the largest speed of the body at the samples, the instants every backend
// and the reference share (a peak between two samples is not looked for: on one grid for
// all, the values compare). The first observable added the registry's way: this file and
// one row in observable_registry.cpp.
#include <algorithm>

#include "observe/observable_measure.hpp"

namespace bb {

ObservableValue measure_max_speed(const Scene&, const Observe& observe,
                                  const Trajectory& trajectory, const EventTrace*) {
  double fastest = 0.0;
  for (const State& s : trajectory.states)
    fastest = std::max(fastest, s[observe.body].velocity.norm());
  return {fastest, ""};
}

}  // namespace bb
