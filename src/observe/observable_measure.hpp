// How one kind of observable is measured: the signature every kind's measurement has, so
// that the registry (observable_registry.hpp) maps a kind to its function and nothing else
// matches kinds by name.
#pragma once

#include <optional>
#include <string>

#include "metrics/trajectory.hpp"
#include "study/scene.hpp"

namespace bb {

/// A measured value, or the reason there is none for this run.
struct ObservableValue {
  std::optional<double> value;
  std::string note;  ///< why `value` is empty
};

/// The value of `observe` on `trajectory` (never empty of samples); `reference` holds the
/// reference's events where a kind measures from them (rest_creep), else nullptr.
using MeasureFn = ObservableValue (*)(const Scene& scene, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace* reference);

/// The value of the observed body's state whose zero crossings a kind watches as events
/// (time_above: the centre's height above its level): continuous along a motion, it is read
/// at every step of a stepped backend and is an event function of the reference's.
using CrossingFn = double (*)(const World& world, const Observe& observe, const BodyState& body);

/// The value every run's is compared with when a formula gives it from the scene alone
/// (terminal_velocity's terminal speed); nullopt where the formula does not apply.
using FormulaFn = std::optional<double> (*)(const Scene& scene, const Observe& observe);

}  // namespace bb
