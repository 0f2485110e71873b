// The registry of observables: per kind of the case format (scene/metric_names.hpp says
// what each needs watched), the function that measures it and, where a formula gives its
// value from the scene alone, that formula. A new observable is one file in metrics/ (its
// MeasureFn) plus one line here in observable_registry.cpp and one in the kind table.
#pragma once

#include <string>

#include "metrics/observable_measure.hpp"

namespace bb {

struct ObservableMeasure {
  MeasureFn measure = nullptr;
  FormulaFn formula = nullptr;  ///< null: compared with the reference's own measurement
};

/// How `kind` is measured, or nullptr for a kind this version does not know.
const ObservableMeasure* observable_measure(const std::string& kind);

}  // namespace bb
