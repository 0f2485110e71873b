// A run compared with its kept results (`check --baseline DIR`): each error metric and each
// observable's distance from its reference value, per backend and dt, worse, better or
// unchanged by the case's [baseline] tolerance; a status that left `ok` is worse.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// Every row of `now` against the row of `baseline` with the same backend and dt (a step
/// matches to 1e-9 of itself), and every row of `baseline` that `now` lacks. An error
/// metric's value is the error; an observable's, its distance from its reference value
/// (metric_value), compared only where it has one. Worse: larger than the baseline by more
/// than both `options.tolerance` times it and `options.floor`.
std::vector<BaselineComparison> compare_with_baseline(const std::vector<const RunRecord*>& baseline,
                                                      const std::vector<const RunRecord*>& now,
                                                      const BaselineOptions& options);

/// now / before: how many times worse (below 1: better); infinite from 0.
double change_ratio(const BaselineComparison& c);

}  // namespace bb
