// Where a report's time went: the wall-clock seconds of each part of the work (accuracy
// runs, the cost pass, the stability search, sweeps), in total and per case.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The index page's section: one row for the whole report, then one per case, the slowest
/// first. Empty when nothing was timed.
std::string time_spent_section(const std::vector<CaseResults>& all);

}  // namespace bb
