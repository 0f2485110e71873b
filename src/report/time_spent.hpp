// Where a report's time went: the wall-clock seconds of each part of the work (accuracy
// runs, the cost pass, the stability search, sweeps), in total and per case.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The index page's section: one row for the whole report, then one per case, the slowest
/// first, beside what the accuracy runs cost per run and what their steps alone take on
/// `jobs` cores (a floor no overhead removed can go below). Empty when nothing was timed.
std::string time_spent_section(const std::vector<CaseResults>& all, int jobs);

}  // namespace bb
