// Each run's total energy against time, on an axis that keeps the runs that stay near the
// start readable when another runs away (the runaway is cut at the edge and named).
#pragma once

#include <string>

#include "files/file_batch.hpp"
#include "run/results.hpp"

namespace bb {

/// Draws the energy plot of `results` into `batch` as `name`. Returns why there is no
/// plot, or "" when it was drawn (as gnuplot.hpp's draw).
std::string energy_plot(const CaseResults& results, FileBatch& batch, const std::string& name);

}  // namespace bb
