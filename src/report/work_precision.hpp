// Work-precision: each backend's (cost, error) points over the dt sweep, and the cheapest
// step that reaches a stated error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/table.hpp"
#include "run/results.hpp"

namespace bb {

struct WorkPoint {
  double dt;
  std::optional<double> cost;  ///< seconds per simulated second
  double error;
};

struct WorkSeries {
  std::string backend;
  std::vector<WorkPoint> points;  ///< dt largest first, ok runs with a value only
};

/// One series per backend that has any point for `metric`.
std::vector<WorkSeries> work_series(const CaseResults& results, const std::string& metric);

/// The floor of `metric`: the reference against itself at a 100 times tighter tolerance.
std::optional<double> metric_floor(const CaseResults& results, const std::string& metric);

/// Per backend: the largest dt of the sweep whose error is within `target`, with its cost,
/// or "not reached".
Table cheapest_step_table(const CaseResults& results, const std::string& metric, double target);

}  // namespace bb
