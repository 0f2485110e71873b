// A case's [[sweep]] on its page: each quantity the case observes, and position_max,
// against the swept parameter, one line per backend over the reference; where something
// starts (the onset); how far each backend's result moves between neighbouring values
// (predictability, Chung and Pollard 2016); and every value when there are few.
#pragma once

#include <string>

#include "files/file_batch.hpp"
#include "run/results.hpp"

namespace bb {

/// Draws the sweep as `name` into `batch`; returns why nothing was drawn, else "".
std::string sweep_plot(const CaseResults& results, FileBatch& batch, const std::string& name);

/// The page's sweep section ("" without a sweep); `plot` is the drawn file or "".
std::string sweep_markdown(const CaseResults& results, const std::string& plot);

}  // namespace bb
