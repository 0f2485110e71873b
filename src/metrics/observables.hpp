// Case-specific quantities ([[observe]]) measured on one trajectory.
#pragma once

#include <optional>
#include <string>

#include "metrics/trajectory.hpp"
#include "scene/scene.hpp"

namespace bb {

/// A measured value, or the reason there is none for this run.
struct ObservableValue {
  std::optional<double> value;
  std::string note;  ///< why `value` is empty
};

ObservableValue measure(const Scene& scene, const Observe& observe, const Trajectory& trajectory);

}  // namespace bb
